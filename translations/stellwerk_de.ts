<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de" sourcelanguage="en">
<context>
    <name>AboutBox</name>
    <message>
        <source>About Stellwerk</source>
        <translation>Über Stellwerk</translation>
    </message>
    <message>
        <source>Stellwerk is a desktop control station for Märklin digital model railways that speaks the CAN protocol of the Central Station 2 and 3.</source>
        <translation>Stellwerk ist ein Stellpult am Computer für digitale Märklin-Modellbahnen und spricht das CAN-Protokoll der Central Station 2 und 3.</translation>
    </message>
    <message>
        <source>Built with Qt %1, running on Qt %2.</source>
        <translation>Erstellt mit Qt %1, läuft unter Qt %2.</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::FrameDecoderPanel</name>
    <message>
        <source>unreadable</source>
        <translation>unlesbar</translation>
    </message>
    <message>
        <source>Open capture</source>
        <translation>Mitschnitt öffnen</translation>
    </message>
    <message>
        <source>Captures (*.log *.txt *.can);;All files (*)</source>
        <translation>Mitschnitte (*.log *.txt *.can);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>%1 could not be read: %2</source>
        <translation>%1 konnte nicht gelesen werden: %2</translation>
    </message>
    <message>
        <source>%1 is larger than %2 MB; open a shorter excerpt.</source>
        <translation>%1 ist größer als %2 MB; bitte einen kürzeren Ausschnitt öffnen.</translation>
    </message>
    <message>
        <source>Paste CAN frames, one per line, as written in the Märklin document (00004711 5 00 00 00 00 00), by candump (00004711#0000000000) or as 13-byte network frames in hex. Lines starting with # are ignored.</source>
        <translation>CAN-Telegramme zeilenweise einfügen: wie im Märklin-Dokument (00004711 5 00 00 00 00 00), wie von candump (00004711#0000000000) oder als 13-Byte-Netzwerktelegramm in Hex. Zeilen, die mit # beginnen, werden übergangen.</translation>
    </message>
    <message>
        <source>00084711 6 00 00 C0 03 01 20</source>
        <translation>00084711 6 00 00 C0 03 01 20</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>Zeile</translation>
    </message>
    <message>
        <source>Frame</source>
        <translation>Telegramm</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Meldung</translation>
    </message>
    <message>
        <source>Details</source>
        <translation>Details</translation>
    </message>
    <message>
        <source>&amp;Open capture…</source>
        <translation>Mitschnitt ö&amp;ffnen…</translation>
    </message>
    <message>
        <source>C&amp;lear</source>
        <translation>&amp;Leeren</translation>
    </message>
    <message numerus="yes">
        <source>%n frame(s)</source>
        <translation>
            <numerusform>%n Telegramm</numerusform>
            <numerusform>%n Telegramme</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n frame(s), %1 not decodable</source>
        <translation>
            <numerusform>%n Telegramm, %1 nicht dekodierbar</numerusform>
            <numerusform>%n Telegramme, %1 nicht dekodierbar</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 (response)</source>
        <translation>%1 (Antwort)</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::LanguageMenu</name>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::MainWindow</name>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>Close the window and end Stellwerk</source>
        <translation>Fenster schließen und Stellwerk beenden</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;About Stellwerk</source>
        <translation>Ü&amp;ber Stellwerk</translation>
    </message>
    <message>
        <source>Show the version of Stellwerk and of Qt</source>
        <translation>Versionen von Stellwerk und Qt anzeigen</translation>
    </message>
    <message>
        <source>No station connected</source>
        <translation>Keine Zentrale verbunden</translation>
    </message>
    <message>
        <source>The translation &quot;%1&quot; could not be loaded.</source>
        <translation>Die Übersetzung „%1“ konnte nicht geladen werden.</translation>
    </message>
    <message>
        <source>Frame decoder</source>
        <translation>Telegramm-Decoder</translation>
    </message>
</context>
</TS>
