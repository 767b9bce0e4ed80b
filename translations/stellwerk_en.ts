<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en" sourcelanguage="en">
<context>
    <name>AboutBox</name>
    <message>
        <source>About Stellwerk</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stellwerk is a desktop control station for Märklin digital model railways that speaks the CAN protocol of the Central Station 2 and 3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Built with Qt %1, running on Qt %2.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::ConnectDialog</name>
    <message>
        <source>Connect to a station</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Station &amp;address:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Examples:
udp://192.168.2.5 — a CS2 with its CAN-UDP gateway switched on
tcp://192.168.2.5 — a CS3, or a CS2 over TCP
can://socketcan/can0 — a Gleisbox through a CAN adapter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Use the simulated station (demo layout)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Connect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enter the station&apos;s address, or use the simulated station.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This address cannot be used: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::ConnectionStatus</name>
    <message>
        <source>Simulated CS2 (demo layout)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CS2 at %1 (UDP)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CS2 at %1 (TCP)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CAN interface %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Station &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No station connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — connecting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — ready: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — station silent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — failed: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>listing the devices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>waking up the Gleisbox</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading the devices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>files</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>locomotive and contact states</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1, %2, %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n locomotive(s)</source>
        <translation>
            <numerusform>%n locomotive</numerusform>
            <numerusform>%n locomotives</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n accessory(s)</source>
        <translation>
            <numerusform>%n accessory</numerusform>
            <numerusform>%n accessories</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n page(s)</source>
        <translation>
            <numerusform>%n page</numerusform>
            <numerusform>%n pages</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 — loading configuration %2/%3: %4</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::ContactTableModel</name>
    <message>
        <source>Contact</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>State</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Last change</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>occupied</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>free</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::FrameDecoderPanel</name>
    <message>
        <source>unreadable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open capture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Captures (*.log *.txt *.can);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 could not be read: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is larger than %2 MB; open a shorter excerpt.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paste CAN frames, one per line, as written in the Märklin document (00004711 5 00 00 00 00 00), by candump (00004711#0000000000) or as 13-byte network frames in hex. Lines starting with # are ignored.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>00084711 6 00 00 C0 03 01 20</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Message</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Details</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Open capture…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>C&amp;lear</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n frame(s)</source>
        <translation>
            <numerusform>%n frame</numerusform>
            <numerusform>%n frames</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n frame(s), %1 not decodable</source>
        <translation>
            <numerusform>%n frame, %1 not decodable</numerusform>
            <numerusform>%n frames, %1 not decodable</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 (response)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::LanguageMenu</name>
    <message>
        <source>&amp;Language</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::LayoutOverview</name>
    <message>
        <source>No station connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Track power: not reported yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Track power: on, trains may run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Track power: on, every train halted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Track power: off (stop)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Locomotives</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feedback contacts</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::LocomotiveTableModel</name>
    <message>
        <source>Locomotive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Address</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Functions on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>backward</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>forward</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::MainWindow</name>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close the window and end Stellwerk</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;About Stellwerk</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the version of Stellwerk and of Qt</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The translation &quot;%1&quot; could not be loaded.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Frame decoder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Station</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Connect…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose the station to connect to, or the simulated one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Layout</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
