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
    <name>AccessoryIcon</name>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <source>Straight</source>
        <translation>Gerade</translation>
    </message>
    <message>
        <source>Diverging</source>
        <translation>Abzweig</translation>
    </message>
    <message>
        <source>Right</source>
        <translation>Rechts</translation>
    </message>
    <message>
        <source>Left</source>
        <translation>Links</translation>
    </message>
    <message>
        <source>Straight, diverging</source>
        <translation>Gerade, Abzweig</translation>
    </message>
    <message>
        <source>Diverging, straight</source>
        <translation>Abzweig, Gerade</translation>
    </message>
    <message>
        <source>Hp0</source>
        <translation>Hp0</translation>
    </message>
    <message>
        <source>Hp1</source>
        <translation>Hp1</translation>
    </message>
    <message>
        <source>Sh1</source>
        <translation>Sh1</translation>
    </message>
    <message>
        <source>Hp2</source>
        <translation>Hp2</translation>
    </message>
    <message>
        <source>Sh0</source>
        <translation>Sh0</translation>
    </message>
    <message>
        <source>Uncouple</source>
        <translation>Entkuppeln</translation>
    </message>
    <message>
        <source>Rest</source>
        <translation>Grundstellung</translation>
    </message>
    <message>
        <source>On</source>
        <translation>An</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <source>Track %1</source>
        <translation>Gleis %1</translation>
    </message>
    <message>
        <source>Green</source>
        <translation>Grün</translation>
    </message>
    <message>
        <source>Red</source>
        <translation>Rot</translation>
    </message>
</context>
<context>
    <name>AnnouncedStateText</name>
    <message>
        <source>not active</source>
        <translation>nicht aktiv</translation>
    </message>
    <message>
        <source>active</source>
        <translation>aktiv</translation>
    </message>
    <message>
        <source>running</source>
        <translation>läuft</translation>
    </message>
    <message>
        <source>free</source>
        <translation>frei</translation>
    </message>
    <message>
        <source>occupied</source>
        <translation>besetzt</translation>
    </message>
    <message>
        <source>waiting</source>
        <translation>wartet</translation>
    </message>
    <message>
        <source>reserved</source>
        <translation>reserviert</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
</context>
<context>
    <name>BlockDescription</name>
    <message>
        <source>Block %1 &apos;%2&apos;</source>
        <translation>Block %1 „%2“</translation>
    </message>
    <message numerus="yes">
        <source>%n tile(s), %1 mm</source>
        <translation>
            <numerusform>%n Feld, %1 mm</numerusform>
            <numerusform>%n Felder, %1 mm</numerusform>
        </translation>
    </message>
    <message>
        <source>Contact %1</source>
        <translation>Kontakt %1</translation>
    </message>
    <message>
        <source>Contact %1 &apos;%2&apos;</source>
        <translation>Kontakt %1 „%2“</translation>
    </message>
    <message>
        <source>%1 of feedback device %2</source>
        <translation>%1 an Rückmeldegerät %2</translation>
    </message>
    <message>
        <source>Signal &apos;%1&apos;</source>
        <translation>Signal „%1“</translation>
    </message>
    <message>
        <source>Signal %1</source>
        <translation>Signal %1</translation>
    </message>
    <message>
        <source>A signal</source>
        <translation>Ein Signal</translation>
    </message>
    <message>
        <source>%1, for trains towards end %2</source>
        <translation>%1, für Züge in Richtung Ende %2</translation>
    </message>
    <message>
        <source>From end %1 (%2):</source>
        <translation>Von Ende %1 (%2):</translation>
    </message>
    <message>
        <source>to block %1 &apos;%2&apos;, end %3</source>
        <translation>nach Block %1 „%2“, Ende %3</translation>
    </message>
    <message>
        <source>directly</source>
        <translation>direkt</translation>
    </message>
    <message numerus="yes">
        <source>over %n tile(s) of track without a contact</source>
        <translation>
            <numerusform>über %n Feld Gleis ohne Kontakt</numerusform>
            <numerusform>über %n Felder Gleis ohne Kontakt</numerusform>
        </translation>
    </message>
    <message>
        <source>the turnout at %1 %2</source>
        <translation>die Weiche bei %1 %2</translation>
    </message>
    <message>
        <source>turnout %1 %2</source>
        <translation>Weiche %1 %2</translation>
    </message>
    <message>
        <source>turnout %1 &apos;%2&apos; %3</source>
        <translation>Weiche %1 „%2“ %3</translation>
    </message>
    <message>
        <source>over %1</source>
        <translation>über %1</translation>
    </message>
    <message numerus="yes">
        <source>across the crossing(s) at %1</source>
        <translation>
            <numerusform>über die Kreuzung bei %1</numerusform>
            <numerusform>über die Kreuzungen bei %1</numerusform>
        </translation>
    </message>
    <message>
        <source>&apos;%1&apos;</source>
        <translation>„%1“</translation>
    </message>
    <message numerus="yes">
        <source>set by route(s) %1</source>
        <translation>
            <numerusform>gestellt von Fahrstraße %1</numerusform>
            <numerusform>gestellt von den Fahrstraßen %1</numerusform>
        </translation>
    </message>
    <message>
        <source>The track ends at a buffer stop.</source>
        <translation>Das Gleis endet an einem Prellbock.</translation>
    </message>
    <message>
        <source>The track ends at a turntable.</source>
        <translation>Das Gleis endet an einer Drehscheibe.</translation>
    </message>
    <message>
        <source>The track ends without a buffer stop.</source>
        <translation>Das Gleis endet ohne Prellbock.</translation>
    </message>
    <message>
        <source>No way leads from here to another block.</source>
        <translation>Von hier führt kein Weg zu einem anderen Block.</translation>
    </message>
    <message>
        <source>page %1, column %2, row %3</source>
        <translation>Seite %1, Spalte %2, Zeile %3</translation>
    </message>
    <message>
        <source>straight</source>
        <translation>gerade</translation>
    </message>
    <message>
        <source>diverging</source>
        <translation>abzweigend</translation>
    </message>
    <message>
        <source>left</source>
        <translation>links</translation>
    </message>
    <message>
        <source>right</source>
        <translation>rechts</translation>
    </message>
    <message>
        <source>straight and diverging</source>
        <translation>gerade und abzweigend</translation>
    </message>
    <message>
        <source>diverging and straight</source>
        <translation>abzweigend und gerade</translation>
    </message>
    <message>
        <source>across</source>
        <translation>kreuzend</translation>
    </message>
    <message>
        <source>Contacts:</source>
        <translation>Kontakte:</translation>
    </message>
    <message>
        <source>Signals:</source>
        <translation>Signale:</translation>
    </message>
</context>
<context>
    <name>CorrectionText</name>
    <message>
        <source>%1: the station carried out a command late that had failed (%2); it stays, as it brings nothing into motion.</source>
        <translation>%1: Die Zentrale hat einen fehlgeschlagenen Befehl verspätet ausgeführt (%2); das bleibt so, denn es setzt nichts in Bewegung.</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>angehalten</translation>
    </message>
    <message>
        <source>set back to %1</source>
        <translation>zurückgesetzt auf %1</translation>
    </message>
    <message>
        <source>%1: the station carried out a command late that had failed (%2); %3.</source>
        <translation>%1: Die Zentrale hat einen fehlgeschlagenen Befehl verspätet ausgeführt (%2); %3.</translation>
    </message>
    <message>
        <source>%1: a command that had failed (%2) could still reach the station; %3.</source>
        <translation>%1: Ein fehlgeschlagener Befehl (%2) hätte die Zentrale noch erreichen können; %3.</translation>
    </message>
    <message>
        <source>Accessory %1</source>
        <translation>Magnetartikel %1</translation>
    </message>
    <message>
        <source>Address %1</source>
        <translation>Adresse %1</translation>
    </message>
    <message>
        <source>Track power</source>
        <translation>Gleisspannung</translation>
    </message>
    <message>
        <source>speed %1 %</source>
        <translation>Geschwindigkeit %1 %</translation>
    </message>
    <message>
        <source>backward</source>
        <translation>rückwärts</translation>
    </message>
    <message>
        <source>forward</source>
        <translation>vorwärts</translation>
    </message>
    <message>
        <source>F%1 on</source>
        <translation>F%1 an</translation>
    </message>
    <message>
        <source>F%1 off</source>
        <translation>F%1 aus</translation>
    </message>
    <message>
        <source>position %1</source>
        <translation>Stellung %1</translation>
    </message>
    <message>
        <source>on</source>
        <translation>an</translation>
    </message>
    <message>
        <source>off</source>
        <translation>aus</translation>
    </message>
</context>
<context>
    <name>FunctionIcons</name>
    <message>
        <source>Function</source>
        <translation>Funktion</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Licht</translation>
    </message>
    <message>
        <source>Interior light</source>
        <translation>Innenbeleuchtung</translation>
    </message>
    <message>
        <source>Cab light</source>
        <translation>Führerstandsbeleuchtung</translation>
    </message>
    <message>
        <source>Sound</source>
        <translation>Geräusch</translation>
    </message>
    <message>
        <source>Horn</source>
        <translation>Horn</translation>
    </message>
    <message>
        <source>Whistle</source>
        <translation>Pfeife</translation>
    </message>
    <message>
        <source>Bell</source>
        <translation>Glocke</translation>
    </message>
    <message>
        <source>Smoke</source>
        <translation>Rauchgenerator</translation>
    </message>
    <message>
        <source>Coupler</source>
        <translation>Kupplung</translation>
    </message>
    <message>
        <source>Shunting speed</source>
        <translation>Rangiergang</translation>
    </message>
    <message>
        <source>Brake sound</source>
        <translation>Bremsgeräusch</translation>
    </message>
    <message>
        <source>Pantograph</source>
        <translation>Stromabnehmer</translation>
    </message>
    <message>
        <source>Acceleration delay off</source>
        <translation>ABV aus</translation>
    </message>
    <message>
        <source>Announcement</source>
        <translation>Ansage</translation>
    </message>
</context>
<context>
    <name>GraphProblemText</name>
    <message>
        <source>Page %1, column %2, row %3: %4</source>
        <translation>Seite %1, Spalte %2, Zeile %3: %4</translation>
    </message>
    <message>
        <source>The track ends here without a buffer stop, or does not meet the track of the tile beside it; add the missing track or a buffer stop, or turn a tile.</source>
        <translation>Das Gleis endet hier ohne Prellbock oder trifft nicht auf das Gleis des Nachbarfelds; ergänzen Sie das fehlende Gleis oder einen Prellbock, oder drehen Sie ein Feld.</translation>
    </message>
    <message>
        <source>This tile (%1) joins no other track; move it onto the track or remove it.</source>
        <translation>Dieses Feld (%1) ist mit keinem anderen Gleis verbunden; setzen Sie es auf das Gleis oder entfernen Sie es.</translation>
    </message>
    <message>
        <source>%1 has a side without track, so the way through it there leads nowhere; add the track or a buffer stop.</source>
        <translation>%1 hat eine Seite ohne Gleis, der Weg dorthin führt also ins Leere; ergänzen Sie das Gleis oder einen Prellbock.</translation>
    </message>
    <message>
        <source>The track from here to the next turnout or end has no contact, so a train there cannot be seen; add a contact where trains may stop.</source>
        <translation>Das Gleis von hier bis zur nächsten Weiche oder zum Ende hat keinen Kontakt, ein Zug darauf ist also nicht zu sehen; setzen Sie einen Kontakt, wo Züge halten können.</translation>
    </message>
    <message>
        <source>The arrow names page %1, which the track plan does not have; the track ends here.</source>
        <translation>Der Pfeil nennt die Seite %1, die der Gleisplan nicht hat; das Gleis endet hier.</translation>
    </message>
    <message>
        <source>The arrow leads to page %1, whose file is missing; the track ends here.</source>
        <translation>Der Pfeil führt zur Seite %1, deren Datei fehlt; das Gleis endet hier.</translation>
    </message>
    <message>
        <source>The arrow to page %1 has no arrow back on that page, so the track ends here; add one where the track goes on.</source>
        <translation>Der Pfeil zur Seite %1 hat dort keinen Pfeil zurück, das Gleis endet also hier; setzen Sie einen, wo das Gleis weitergeht.</translation>
    </message>
    <message>
        <source>%1 is drawn twice on this page, on two stretches of track; one contact can watch only one block, so both are taken as block &apos;%2&apos;.</source>
        <translation>%1 ist auf dieser Seite zweimal gezeichnet, auf zwei Gleisabschnitten; ein Kontakt kann nur einen Block überwachen, beide gelten daher als Block „%2“.</translation>
    </message>
    <message>
        <source>%1 is drawn on another page as well, and the drawings join different track; make the pages agree.</source>
        <translation>%1 ist auch auf einer anderen Seite gezeichnet, und die Zeichnungen verbinden verschiedene Gleise; gleichen Sie die Seiten an.</translation>
    </message>
    <message>
        <source>A route sets %1 so that it leads from no block to another as the plan draws it; check the route&apos;s turnouts against the plan.</source>
        <translation>Eine Fahrstraße stellt %1 so, dass sie nach der Zeichnung von keinem Block zu einem anderen führt; prüfen Sie die Weichen der Fahrstraße am Gleisplan.</translation>
    </message>
    <message>
        <source>Route %1 sets turnouts that together lead from no block to another as the plan draws them; check the route&apos;s turnouts against the plan.</source>
        <translation>Fahrstraße %1 stellt Weichen, die nach der Zeichnung zusammen von keinem Block zu einem anderen führen; prüfen Sie die Weichen der Fahrstraße am Gleisplan.</translation>
    </message>
    <message>
        <source>A way over this tile needs %1 in two positions at once (it is drawn more than once, or passed twice), so that way is left out; give the drawings their own articles if they are separate turnouts.</source>
        <translation>Ein Weg über dieses Feld braucht %1 in zwei Stellungen zugleich (sie ist mehrfach gezeichnet oder wird zweimal befahren), dieser Weg entfällt daher; geben Sie den Zeichnungen eigene Artikel, wenn es getrennte Weichen sind.</translation>
    </message>
    <message>
        <source>From this tile the track branches into more ways than are followed; add contacts between the turnouts so that it splits into blocks.</source>
        <translation>Von diesem Feld aus verzweigt sich das Gleis in mehr Wege als verfolgt werden; setzen Sie Kontakte zwischen die Weichen, damit es sich in Blöcke teilt.</translation>
    </message>
    <message numerus="yes">
        <source>The drawing of the track plan has %n problem(s):</source>
        <translation>
            <numerusform>Die Zeichnung des Gleisplans hat %n Problem:</numerusform>
            <numerusform>Die Zeichnung des Gleisplans hat %n Probleme:</numerusform>
        </translation>
    </message>
    <message>
        <source>&apos;%1&apos;</source>
        <translation>„%1“</translation>
    </message>
    <message>
        <source>The turnout</source>
        <translation>Die Weiche</translation>
    </message>
    <message>
        <source>Turnout %1</source>
        <translation>Weiche %1</translation>
    </message>
    <message>
        <source>Turnout %1 &apos;%2&apos;</source>
        <translation>Weiche %1 „%2“</translation>
    </message>
    <message>
        <source>Contact %1</source>
        <translation>Kontakt %1</translation>
    </message>
    <message>
        <source>Contact %1 &apos;%2&apos;</source>
        <translation>Kontakt %1 „%2“</translation>
    </message>
</context>
<context>
    <name>NotReported</name>
    <message>
        <source>not reported</source>
        <translation>nicht gemeldet</translation>
    </message>
    <message>
        <source>Not reported: the station is silent or being reconnected. This is the last state it reported; it may no longer be true.</source>
        <translation>Nicht gemeldet: Die Zentrale antwortet nicht oder wird neu verbunden. Das ist der zuletzt gemeldete Zustand; er kann inzwischen anders sein.</translation>
    </message>
</context>
<context>
    <name>StopReasonText</name>
    <message>
        <source>%1 is no longer seen where it stood: place it again</source>
        <translation>%1 ist dort, wo er stand, nicht mehr gemeldet: bitte neu aufgleisen</translation>
    </message>
    <message>
        <source>%1 entered &quot;%2&quot; on the way of %3</source>
        <translation>%1 ist in „%2“ eingefahren, auf dem Fahrweg von %3</translation>
    </message>
    <message>
        <source>%1 ran on into &quot;%2&quot;, which was not reserved for it: track power off</source>
        <translation>%1 ist in „%2“ weitergefahren, das nicht für ihn reserviert war: Gleisspannung aus</translation>
    </message>
    <message>
        <source>%1 stopped: an unknown occupant in &quot;%2&quot; on its way</source>
        <translation>%1 angehalten: „%2“ auf seinem Fahrweg ist unbekannt belegt</translation>
    </message>
    <message>
        <source>%1 did not arrive in &quot;%2&quot; in time: stopped, place it again</source>
        <translation>%1 ist nicht rechtzeitig in „%2“ angekommen: angehalten, bitte neu aufgleisen</translation>
    </message>
    <message>
        <source>turnout %1 was not confirmed in position %2 after %3 attempts: %4 does not depart, its way is given back</source>
        <translation>Weiche %1 wurde nach %3 Versuchen nicht in Stellung %2 bestätigt: %4 fährt nicht ab, der Fahrweg wird freigegeben</translation>
    </message>
    <message>
        <source>turnout %1 was switched to position %2 on the way reserved for %3: stopped</source>
        <translation>Weiche %1 wurde auf dem für %3 reservierten Fahrweg in Stellung %2 gestellt: angehalten</translation>
    </message>
</context>
<context>
    <name>TileMenu</name>
    <message>
        <source>Locomotive on this contact</source>
        <translation>Lok auf diesem Kontakt</translation>
    </message>
    <message>
        <source>Not known</source>
        <translation>Nicht bekannt</translation>
    </message>
    <message>
        <source>Run from Stellwerk</source>
        <translation>Von Stellwerk stellen</translation>
    </message>
    <message>
        <source>Run from the station&apos;s memory (%1)</source>
        <translation>Aus dem Speicher der Zentrale stellen (%1)</translation>
    </message>
</context>
<context>
    <name>TrackTileInfo</name>
    <message>
        <source>Straight track</source>
        <translation>Gerades Gleis</translation>
    </message>
    <message>
        <source>Curve</source>
        <translation>Bogen</translation>
    </message>
    <message>
        <source>Double curve</source>
        <translation>Doppelbogen</translation>
    </message>
    <message>
        <source>Crossing</source>
        <translation>Kreuzung</translation>
    </message>
    <message>
        <source>Underpass</source>
        <translation>Unterführung</translation>
    </message>
    <message>
        <source>Buffer stop</source>
        <translation>Prellbock</translation>
    </message>
    <message>
        <source>Tunnel</source>
        <translation>Tunnel</translation>
    </message>
    <message>
        <source>Left turnout</source>
        <translation>Weiche links</translation>
    </message>
    <message>
        <source>Right turnout</source>
        <translation>Weiche rechts</translation>
    </message>
    <message>
        <source>Y turnout</source>
        <translation>Y-Weiche</translation>
    </message>
    <message>
        <source>Three-way turnout</source>
        <translation>Dreiwegweiche</translation>
    </message>
    <message>
        <source>Double slip</source>
        <translation>Doppelkreuzweiche</translation>
    </message>
    <message>
        <source>Double slip (two drives)</source>
        <translation>Doppelkreuzweiche (zwei Antriebe)</translation>
    </message>
    <message>
        <source>Scissors crossover</source>
        <translation>Hosenträger</translation>
    </message>
    <message>
        <source>S88 contact</source>
        <translation>Rückmeldekontakt (S88)</translation>
    </message>
    <message>
        <source>S88 contact (curve)</source>
        <translation>Rückmeldekontakt (S88, Bogen)</translation>
    </message>
    <message>
        <source>S88 contact (double curve)</source>
        <translation>Rückmeldekontakt (S88, Doppelbogen)</translation>
    </message>
    <message>
        <source>Link to a page</source>
        <translation>Verweis auf eine Seite</translation>
    </message>
    <message>
        <source>Route button</source>
        <translation>Fahrstraßentaste</translation>
    </message>
    <message>
        <source>Text</source>
        <translation>Text</translation>
    </message>
    <message>
        <source>Level crossing</source>
        <translation>Bahnübergang</translation>
    </message>
    <message>
        <source>Slip turnout</source>
        <translation>Kreuzungsweiche</translation>
    </message>
    <message>
        <source>Semaphore signal</source>
        <translation>Formsignal</translation>
    </message>
    <message>
        <source>Signal</source>
        <translation>Signal</translation>
    </message>
    <message>
        <source>Uncoupler</source>
        <translation>Entkupplungsgleis</translation>
    </message>
    <message>
        <source>Lamp</source>
        <translation>Lampe</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Ausgang</translation>
    </message>
    <message>
        <source>Turntable</source>
        <translation>Drehscheibe</translation>
    </message>
    <message>
        <source>Transfer table</source>
        <translation>Schiebebühne</translation>
    </message>
    <message>
        <source>Unknown element (%1)</source>
        <translation>Unbekanntes Element (%1)</translation>
    </message>
    <message>
        <source>Stop (Hp0)</source>
        <translation>Halt (Hp0)</translation>
    </message>
    <message>
        <source>Proceed (Hp1)</source>
        <translation>Fahrt (Hp1)</translation>
    </message>
    <message>
        <source>Slow (Hp2)</source>
        <translation>Langsamfahrt (Hp2)</translation>
    </message>
    <message>
        <source>Shunting (Sh1)</source>
        <translation>Rangierfahrt (Sh1)</translation>
    </message>
    <message>
        <source>Stop (Sh0)</source>
        <translation>Halt (Sh0)</translation>
    </message>
    <message>
        <source>Left</source>
        <translation>Links</translation>
    </message>
    <message>
        <source>Straight</source>
        <translation>Gerade</translation>
    </message>
    <message>
        <source>Right</source>
        <translation>Rechts</translation>
    </message>
    <message>
        <source>Diverging</source>
        <translation>Abzweig</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <source>On</source>
        <translation>An</translation>
    </message>
    <message>
        <source>Position %1</source>
        <translation>Stellung %1</translation>
    </message>
    <message>
        <source>Accessory %1</source>
        <translation>Magnetartikel %1</translation>
    </message>
    <message>
        <source>Contact %1 (device %2)</source>
        <translation>Kontakt %1 (Gerät %2)</translation>
    </message>
    <message>
        <source>Route %1</source>
        <translation>Fahrstraße %1</translation>
    </message>
</context>
<context>
    <name>TrainStateText</name>
    <message>
        <source>automatic, waiting</source>
        <translation>automatisch, wartet</translation>
    </message>
    <message>
        <source>automatic, setting its way</source>
        <translation>automatisch, stellt den Fahrweg</translation>
    </message>
    <message>
        <source>automatic, running</source>
        <translation>automatisch, fährt</translation>
    </message>
    <message>
        <source>automatic, braking</source>
        <translation>automatisch, bremst</translation>
    </message>
    <message>
        <source>stopped, waiting for Resume</source>
        <translation>angehalten, wartet auf Fortsetzen</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>angehalten</translation>
    </message>
    <message>
        <source>stopped, state unknown (the station was silent)</source>
        <translation>angehalten, Zustand unbekannt (die Zentrale schwieg)</translation>
    </message>
    <message>
        <source>fault: %1</source>
        <translation>Störung: %1</translation>
    </message>
    <message>
        <source>lost: %1</source>
        <translation>verloren: %1</translation>
    </message>
    <message>
        <source>not placed: %1</source>
        <translation>nicht aufgegleist: %1</translation>
    </message>
    <message>
        <source>not placed</source>
        <translation>nicht aufgegleist</translation>
    </message>
    <message>
        <source>automatic, waiting for Resume</source>
        <translation>automatisch, wartet auf Fortsetzen</translation>
    </message>
    <message>
        <source>manual (taken by a throttle)</source>
        <translation>von Hand (ein Fahrpult hat übernommen)</translation>
    </message>
    <message>
        <source>manual</source>
        <translation>von Hand</translation>
    </message>
    <message>
        <source>none: any free block</source>
        <translation>keiner: ein freier Block</translation>
    </message>
    <message>
        <source>%1%2 (%3 s)</source>
        <translation>%1%2 (%3 s)</translation>
    </message>
    <message>
        <source>%1, done</source>
        <translation>%1, erledigt</translation>
    </message>
    <message>
        <source>%1, loop</source>
        <translation>%1, im Kreis</translation>
    </message>
    <message>
        <source>%1, once</source>
        <translation>%1, einmal</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::AftermathMenu</name>
    <message numerus="yes">
        <source>The layout is back in step: %n states read again.</source>
        <translation>
            <numerusform>Die Anlage ist wieder im Takt: %n Zustand neu gelesen.</numerusform>
            <numerusform>Die Anlage ist wieder im Takt: %n Zustände neu gelesen.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The layout is back in step, but %n states got no answer.</source>
        <translation>
            <numerusform>Die Anlage ist wieder im Takt, aber auf %n Abfrage kam keine Antwort.</numerusform>
            <numerusform>Die Anlage ist wieder im Takt, aber auf %n Abfragen kam keine Antwort.</numerusform>
        </translation>
    </message>
    <message>
        <source>Stopping every locomotive and reading every state again…</source>
        <translation>Alle Loks werden angehalten und alle Zustände neu gelesen …</translation>
    </message>
    <message>
        <source>Sending every locomotive its confirmed speed and reading every state again…</source>
        <translation>Jede Lok bekommt ihre bestätigte Geschwindigkeit, alle Zustände werden neu gelesen …</translation>
    </message>
    <message>
        <source>After a &amp;failed command</source>
        <translation>Nach einem &amp;fehlgeschlagenen Befehl</translation>
    </message>
    <message>
        <source>&amp;Bring back what the station last confirmed</source>
        <translation>&amp;Zurückholen, was die Zentrale zuletzt bestätigt hat</translation>
    </message>
    <message>
        <source>&amp;Stop every locomotive that had one</source>
        <translation>Jede betroffene Lok an&amp;halten</translation>
    </message>
    <message>
        <source>Bring the layout back in &amp;step</source>
        <translation>Anlage wieder in &amp;Takt bringen</translation>
    </message>
    <message>
        <source>Sends every locomotive the speed the station last confirmed (or stops them all, as chosen under After a failed command) and reads every state again</source>
        <translation>Schickt jeder Lok die zuletzt von der Zentrale bestätigte Geschwindigkeit (oder hält alle an, je nach Wahl unter „Nach einem fehlgeschlagenen Befehl“) und liest alle Zustände neu</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::AutomaticPanel</name>
    <message>
        <source>Trains&apos; book: %1</source>
        <translation>Gespeicherte Züge: %1</translation>
    </message>
    <message>
        <source>Train</source>
        <translation>Zug</translation>
    </message>
    <message>
        <source>Block</source>
        <translation>Block</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>Destination</source>
        <translation>Ziel</translation>
    </message>
    <message>
        <source>Schedule</source>
        <translation>Fahrplan</translation>
    </message>
    <message>
        <source>&amp;Place…</source>
        <translation>&amp;Aufgleisen…</translation>
    </message>
    <message>
        <source>Put a locomotive in a block of the track plan, facing one end</source>
        <translation>Eine Lok in einen Block des Gleisbilds stellen, mit der Spitze zu einem Ende</translation>
    </message>
    <message>
        <source>S&amp;tart</source>
        <translation>S&amp;tarten</translation>
    </message>
    <message>
        <source>The automation drives the train from where it stands</source>
        <translation>Die Automatik fährt den Zug von dort, wo er steht</translation>
    </message>
    <message>
        <source>St&amp;op</source>
        <translation>An&amp;halten</translation>
    </message>
    <message>
        <source>The train stops and becomes manual; its track stays reserved for it</source>
        <translation>Der Zug hält und fährt wieder von Hand; sein Gleis bleibt für ihn reserviert</translation>
    </message>
    <message>
        <source>&amp;Hand back</source>
        <translation>&amp;Zurückgeben</translation>
    </message>
    <message>
        <source>Give a train a throttle took back to the automation, where it stands</source>
        <translation>Einen Zug, den ein Fahrpult übernommen hat, dort, wo er steht, der Automatik zurückgeben</translation>
    </message>
    <message>
        <source>Sche&amp;dule…</source>
        <translation>&amp;Fahrplan…</translation>
    </message>
    <message>
        <source>The blocks the train runs to, how long it stands at each, once or in a loop</source>
        <translation>Die Blöcke, die der Zug anfährt, wie lange er jeweils hält, einmal oder im Kreis</translation>
    </message>
    <message>
        <source>Re&amp;move</source>
        <translation>Ent&amp;fernen</translation>
    </message>
    <message>
        <source>Take the train off the automation and out of the book</source>
        <translation>Den Zug aus der Automatik und aus den gespeicherten Zügen nehmen</translation>
    </message>
    <message>
        <source>&amp;Resume</source>
        <translation>&amp;Fortsetzen</translation>
    </message>
    <message>
        <source>After STOP, a fault or a restart: the automatic trains go on</source>
        <translation>Nach STOP, einer Störung oder einem Neustart: die automatischen Züge fahren weiter</translation>
    </message>
    <message>
        <source>Stop all at next stop</source>
        <translation>Alle am nächsten Halt anhalten</translation>
    </message>
    <message>
        <source>Every automatic train runs on to its next stop and stays there, manual</source>
        <translation>Jeder automatische Zug fährt bis zu seinem nächsten Halt und bleibt dort stehen, von Hand</translation>
    </message>
    <message>
        <source>Automatic operation needs a station (or an opened layout) with a track plan.</source>
        <translation>Der Automatikbetrieb braucht eine Zentrale (oder eine geöffnete Anlage) mit Gleisbild.</translation>
    </message>
    <message>
        <source>Automation is stopped (STOP, a fault or a restart): nothing moves until you press Resume.</source>
        <translation>Die Automatik ist angehalten (STOP, eine Störung oder ein Neustart): nichts fährt, bis Sie Fortsetzen drücken.</translation>
    </message>
    <message>
        <source>No trains yet: place one with Place…, then start it.</source>
        <translation>Noch keine Züge: gleisen Sie einen mit Aufgleisen… auf und starten Sie ihn.</translation>
    </message>
    <message>
        <source>Trains are saved in %1</source>
        <translation>Die Züge werden gespeichert in %1</translation>
    </message>
    <message>
        <source>Last fault: %1</source>
        <translation>Letzte Störung: %1</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::BindingsDialog</name>
    <message>
        <source>Device bindings</source>
        <translation>Geräte-Zuordnungen</translation>
    </message>
    <message>
        <source>Article</source>
        <translation>Artikel</translation>
    </message>
    <message>
        <source>Switched by</source>
        <translation>Geschaltet von</translation>
    </message>
    <message>
        <source>Contact</source>
        <translation>Kontakt</translation>
    </message>
    <message>
        <source>Lit by</source>
        <translation>Gemeldet von</translation>
    </message>
    <message>
        <source>Articles switched by a device instead of the station</source>
        <translation>Artikel, die ein Gerät statt der Zentrale schaltet</translation>
    </message>
    <message>
        <source>Contacts lit by a device instead of an S88 module</source>
        <translation>Kontakte, die ein Gerät statt eines S88-Moduls meldet</translation>
    </message>
    <message>
        <source>RO relay</source>
        <translation>RO-Relais</translation>
    </message>
    <message>
        <source>OpenRailCAN decoder output</source>
        <translation>OpenRailCAN-Dekoderausgang</translation>
    </message>
    <message>
        <source>OpenRailCAN decoder (its position)</source>
        <translation>OpenRailCAN-Dekoder (seine Stellung)</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Hinzufügen</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>RO input</source>
        <translation>RO-Eingang</translation>
    </message>
    <message>
        <source>OpenRailCAN encoder input</source>
        <translation>OpenRailCAN-Enkodereingang</translation>
    </message>
    <message>
        <source>The module&apos;s name</source>
        <translation>Der Name des Moduls</translation>
    </message>
    <message>
        <source>The decoder&apos;s bus id (Ziel-Id)</source>
        <translation>Die Bus-ID des Dekoders (Ziel-Id)</translation>
    </message>
    <message>
        <source>relay </source>
        <translation>Relais </translation>
    </message>
    <message>
        <source>output </source>
        <translation>Ausgang </translation>
    </message>
    <message>
        <source>The encoder&apos;s UID</source>
        <translation>Die UID des Enkoders</translation>
    </message>
    <message>
        <source>input </source>
        <translation>Eingang </translation>
    </message>
    <message>
        <source>Choose an article and the module or decoder that switches it.</source>
        <translation>Wählen Sie einen Artikel und das Modul oder den Dekoder, der ihn schaltet.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is no bus id: write it in hexadecimal, 0x0000 to 0xFFFF.</source>
        <translation>„%1“ ist keine Bus-ID: bitte hexadezimal, 0x0000 bis 0xFFFF.</translation>
    </message>
    <message>
        <source>Choose a contact and the module or encoder that lights it.</source>
        <translation>Wählen Sie einen Kontakt und das Modul oder den Enkoder, der ihn meldet.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is no UID: write it in hexadecimal.</source>
        <translation>„%1“ ist keine UID: bitte hexadezimal.</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>module %1, contact %2</source>
        <translation>Modul %1, Kontakt %2</translation>
    </message>
    <message>
        <source>relay %1 of “%2”</source>
        <translation>Relais %1 von „%2“</translation>
    </message>
    <message>
        <source>OpenRailCAN decoder %1, output %2</source>
        <translation>OpenRailCAN-Dekoder %1, Ausgang %2</translation>
    </message>
    <message>
        <source>OpenRailCAN decoder %1 (its position)</source>
        <translation>OpenRailCAN-Dekoder %1 (seine Stellung)</translation>
    </message>
    <message>
        <source>input %1 of “%2”</source>
        <translation>Eingang %1 von „%2“</translation>
    </message>
    <message>
        <source>OpenRailCAN encoder %1, input %2</source>
        <translation>OpenRailCAN-Enkoder %1, Eingang %2</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::BlockLegend</name>
    <message>
        <source>Blocks:</source>
        <translation>Blöcke:</translation>
    </message>
    <message>
        <source>free</source>
        <translation>frei</translation>
    </message>
    <message>
        <source>reserved</source>
        <translation>reserviert</translation>
    </message>
    <message>
        <source>train in it</source>
        <translation>Zug darin</translation>
    </message>
    <message>
        <source>unknown occupant</source>
        <translation>unbekannt belegt</translation>
    </message>
    <message>
        <source>fault</source>
        <translation>Störung</translation>
    </message>
    <message>
        <source>A train&apos;s blocks are solid and named with it; the blocks and turnouts reserved for its way hatched; a block occupied by something no train can have reached cross-hatched; a train stopped by a fault dotted. Free blocks are outlined while &quot;Blocks&quot; is on.</source>
        <translation>Die Blöcke eines Zuges sind gefüllt und mit seinem Namen beschriftet, die für seinen Fahrweg reservierten Blöcke und Weichen schraffiert, ein Block, den etwas belegt, das kein Zug erreicht haben kann, kreuzschraffiert, ein durch eine Störung angehaltener Zug gepunktet. Freie Blöcke werden umrandet, solange „Blöcke“ eingeschaltet ist.</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::BusMonitorFilterBar</name>
    <message>
        <source>the Loc-ID is not understood; write e.g. 0xC003, 49155 or dcc 3</source>
        <translation>die Loc-ID ist nicht verständlich; z. B. 0xC003, 49155 oder dcc 3 schreiben</translation>
    </message>
    <message>
        <source>the handheld is not understood; write its node, e.g. 43, or its name</source>
        <translation>das Handgerät ist nicht verständlich; seinen Knoten, z. B. 43, oder seinen Namen schreiben</translation>
    </message>
    <message>
        <source>Find text, e.g. speed=0</source>
        <translation>Text suchen, z. B. speed=0</translation>
    </message>
    <message>
        <source>All protocols</source>
        <translation>Alle Protokolle</translation>
    </message>
    <message>
        <source>CS2</source>
        <translation>CS2</translation>
    </message>
    <message>
        <source>M-CAN</source>
        <translation>M-CAN</translation>
    </message>
    <message>
        <source>OpenRailCAN</source>
        <translation>OpenRailCAN</translation>
    </message>
    <message>
        <source>RO</source>
        <translation>RO</translation>
    </message>
    <message>
        <source>Foreign</source>
        <translation>Fremd</translation>
    </message>
    <message>
        <source>Show only frames of one protocol; foreign frames belong to none that is expected on their bus</source>
        <translation>Nur Frames eines Protokolls zeigen; fremde Frames gehören zu keinem, das auf ihrem Bus erwartet wird</translation>
    </message>
    <message>
        <source>Handheld</source>
        <translation>Handgerät</translation>
    </message>
    <message>
        <source>Show only the M-CAN frames of one MS1 handheld: its node (43, or its master&apos;s 42) or the name it sent</source>
        <translation>Nur die M-CAN-Telegramme eines MS1-Handgeräts zeigen: sein Knoten (43, oder der seines Masters, 42) oder der Name, den es gesendet hat</translation>
    </message>
    <message>
        <source>All commands</source>
        <translation>Alle Befehle</translation>
    </message>
    <message>
        <source>Show only frames of one command</source>
        <translation>Nur Telegramme eines Befehls zeigen</translation>
    </message>
    <message>
        <source>Loc-ID</source>
        <translation>Loc-ID</translation>
    </message>
    <message>
        <source>Show only frames for one Loc-ID: 0xC003, 49155 or a protocol and address such as dcc 3, mfx 5, mm2 80</source>
        <translation>Nur Telegramme einer Loc-ID zeigen: 0xC003, 49155 oder Protokoll und Adresse wie dcc 3, mfx 5, mm2 80</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::BusMonitorModel</name>
    <message>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>Direction</source>
        <translation>Richtung</translation>
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
        <source>Frame</source>
        <translation>Telegramm</translation>
    </message>
    <message>
        <source>← received</source>
        <translation>← empfangen</translation>
    </message>
    <message>
        <source>→ sent</source>
        <translation>→ gesendet</translation>
    </message>
    <message>
        <source>Bus</source>
        <translation>Bus</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::BusMonitorPanel</name>
    <message>
        <source>Recording stopped</source>
        <translation>Aufzeichnung beendet</translation>
    </message>
    <message>
        <source>The frames could not be written to %1; recording stopped.</source>
        <translation>Die Telegramme konnten nicht in %1 geschrieben werden; die Aufzeichnung wurde beendet.</translation>
    </message>
    <message>
        <source>Record frames to</source>
        <translation>Telegramme aufzeichnen in</translation>
    </message>
    <message>
        <source>candump logs (*.log);;All files (*)</source>
        <translation>candump-Protokolle (*.log);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Recording not started</source>
        <translation>Aufzeichnung nicht gestartet</translation>
    </message>
    <message>
        <source>%1 cannot be written: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>Open a candump log</source>
        <translation>candump-Protokoll öffnen</translation>
    </message>
    <message>
        <source>Log file</source>
        <translation>Protokolldatei</translation>
    </message>
    <message numerus="yes">
        <source>%Ln row(s) match the filter</source>
        <translation>
            <numerusform>%Ln Zeile passt zum Filter</numerusform>
            <numerusform>%Ln Zeilen passen zum Filter</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>paused, %Ln frame(s) arrived since</source>
        <translation>
            <numerusform>angehalten, seitdem %Ln Telegramm eingetroffen</numerusform>
            <numerusform>angehalten, seitdem %Ln Telegramme eingetroffen</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Resume</source>
        <translation>&amp;Weiter</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pause</translation>
    </message>
    <message>
        <source>Stop adding rows; frames that arrive meanwhile are kept and shown on resume</source>
        <translation>Keine Zeilen mehr anfügen; Telegramme, die inzwischen eintreffen, werden aufbewahrt und bei „Weiter“ gezeigt</translation>
    </message>
    <message>
        <source>C&amp;lear</source>
        <translation>&amp;Leeren</translation>
    </message>
    <message>
        <source>Recording to %1</source>
        <translation>Aufzeichnung in %1</translation>
    </message>
    <message>
        <source>Write every frame from now on to a candump log file</source>
        <translation>Ab jetzt jedes Telegramm in eine candump-Protokolldatei schreiben</translation>
    </message>
    <message>
        <source>&amp;Open log…</source>
        <translation>Protokoll &amp;öffnen …</translation>
    </message>
    <message>
        <source>&amp;Keep:</source>
        <translation>&amp;Behalten:</translation>
    </message>
    <message>
        <source> frames</source>
        <translation> Telegramme</translation>
    </message>
    <message>
        <source>How many frames the table keeps; older ones are dropped</source>
        <translation>Wie viele Telegramme die Tabelle behält; ältere werden verworfen</translation>
    </message>
    <message>
        <source>line %1: %2</source>
        <translation>Zeile %1: %2</translation>
    </message>
    <message>
        <source>%1 cannot be read: %2</source>
        <translation>%1 kann nicht gelesen werden: %2</translation>
    </message>
    <message numerus="yes">
        <source>%Ln frame(s) seen</source>
        <translation>
            <numerusform>%Ln Telegramm erfasst</numerusform>
            <numerusform>%Ln Telegramme erfasst</numerusform>
        </translation>
    </message>
    <message>
        <source>filtering, %1 % done</source>
        <translation>wird gefiltert, %1 % erledigt</translation>
    </message>
    <message numerus="yes">
        <source>%Ln line(s) skipped; %1</source>
        <translation>
            <numerusform>%Ln Zeile übersprungen; %1</numerusform>
            <numerusform>%Ln Zeilen übersprungen; %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Stop re&amp;cording</source>
        <translation>&amp;Aufzeichnung beenden</translation>
    </message>
    <message>
        <source>Re&amp;cord…</source>
        <translation>&amp;Aufzeichnen …</translation>
    </message>
    <message>
        <source>Play the frames of a candump log file instead of the live ones</source>
        <translation>Die Telegramme einer candump-Protokolldatei statt der laufenden abspielen</translation>
    </message>
    <message>
        <source>Replayed %1</source>
        <translation>%1 abgespielt</translation>
    </message>
    <message>
        <source>Replaying %1</source>
        <translation>%1 wird abgespielt</translation>
    </message>
    <message>
        <source>1× (as recorded)</source>
        <translation>1× (wie aufgezeichnet)</translation>
    </message>
    <message>
        <source>2×</source>
        <translation>2×</translation>
    </message>
    <message>
        <source>10×</source>
        <translation>10×</translation>
    </message>
    <message>
        <source>As fast as possible</source>
        <translation>So schnell wie möglich</translation>
    </message>
    <message>
        <source>How fast the log plays</source>
        <translation>Wie schnell das Protokoll abgespielt wird</translation>
    </message>
    <message>
        <source>Res&amp;ume replay</source>
        <translation>Wiedergabe &amp;fortsetzen</translation>
    </message>
    <message>
        <source>Pa&amp;use replay</source>
        <translation>Wiedergabe an&amp;halten</translation>
    </message>
    <message>
        <source>Back to li&amp;ve</source>
        <translation>&amp;Zurück zur Live-Anzeige</translation>
    </message>
    <message>
        <source>Stop the replay, clear the table and show the station&apos;s frames again</source>
        <translation>Wiedergabe beenden, Tabelle leeren und wieder die Telegramme der Zentrale zeigen</translation>
    </message>
    <message>
        <source>station</source>
        <translation>Zentrale</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::ConnectDialog</name>
    <message>
        <source>Connect to a station</source>
        <translation>Mit einer Zentrale verbinden</translation>
    </message>
    <message>
        <source>&amp;Connect</source>
        <translation>&amp;Verbinden</translation>
    </message>
    <message>
        <source>Enter the station&apos;s address, or use the simulated station.</source>
        <translation>Adresse der Zentrale eingeben oder die simulierte Zentrale verwenden.</translation>
    </message>
    <message>
        <source>This address cannot be used: %1</source>
        <translation>Diese Adresse ist nicht verwendbar: %1</translation>
    </message>
    <message>
        <source>&amp;Recent:</source>
        <translation>&amp;Zuletzt:</translation>
    </message>
    <message>
        <source>Choose a station used before…</source>
        <translation>Eine früher verwendete Zentrale wählen …</translation>
    </message>
    <message>
        <source>None yet</source>
        <translation>Noch keine</translation>
    </message>
    <message>
        <source>&amp;Simulated station (demo layout, no hardware needed)</source>
        <translation>&amp;Simulierte Zentrale (Demo-Anlage, keine Hardware nötig)</translation>
    </message>
    <message>
        <source>CS2 or CS3 over &amp;UDP (the CAN gateway, ports 15731/15730)</source>
        <translation>CS2 oder CS3 über &amp;UDP (CAN-Gateway, Ports 15731/15730)</translation>
    </message>
    <message>
        <source>CS2 or CS3 over &amp;TCP (port 15731)</source>
        <translation>CS2 oder CS3 über &amp;TCP (Port 15731)</translation>
    </message>
    <message>
        <source>&amp;Host:</source>
        <translation>&amp;Rechner:</translation>
    </message>
    <message>
        <source>CAN &amp;interface (Gleisbox through a CAN adapter)</source>
        <translation>CAN-&amp;Schnittstelle (Gleisbox über einen CAN-Adapter)</translation>
    </message>
    <message>
        <source>&amp;Interface:</source>
        <translation>S&amp;chnittstelle:</translation>
    </message>
    <message>
        <source>plugin/interface, e.g. socketcan/can0</source>
        <translation>Plugin/Schnittstelle, z. B. socketcan/can0</translation>
    </message>
    <message>
        <source>&amp;Look again</source>
        <translation>&amp;Neu suchen</translation>
    </message>
    <message>
        <source>List the CAN interfaces Qt&apos;s plugins find now</source>
        <translation>Die CAN-Schnittstellen auflisten, die Qts Plugins jetzt finden</translation>
    </message>
    <message>
        <source>&amp;Address:</source>
        <translation>&amp;Adresse:</translation>
    </message>
    <message>
        <source>Further &amp;buses:</source>
        <translation>Weitere &amp;Busse:</translation>
    </message>
    <message>
        <source>Optional: more CAN buses to watch beside the station, such as a USB-CAN adapter wired to relay modules; separate several with commas. Their frames show in the bus monitor.</source>
        <translation>Optional: weitere CAN-Busse, die neben der Zentrale beobachtet werden, etwa ein USB-CAN-Adapter an Relaismodulen; mehrere durch Kommas trennen. Ihre Frames erscheinen im Busmonitor.</translation>
    </message>
    <message>
        <source>The further bus %1 cannot be used: %2</source>
        <translation>Der weitere Bus %1 kann nicht verwendet werden: %2</translation>
    </message>
    <message>
        <source>The further bus %1 is the station&apos;s own address.</source>
        <translation>Der weitere Bus %1 ist die Adresse der Zentrale selbst.</translation>
    </message>
    <message>
        <source>Examples:
udp://192.168.2.5 — a CS2 with its CAN-UDP gateway switched on
tcp://192.168.2.5 — a CS3, or a CS2 over TCP
tcp://127.0.0.1:15731?http=8080 — stellwerk-sim, its pictures on port 8080
can://socketcan/can0 — a Gleisbox through a CAN adapter</source>
        <translation>Beispiele:
udp://192.168.2.5 — eine CS2 mit eingeschaltetem CAN-UDP-Gateway
tcp://192.168.2.5 — eine CS3 oder eine CS2 über TCP
tcp://127.0.0.1:15731?http=8080 — stellwerk-sim, seine Lokbilder auf Port 8080
can://socketcan/can0 — eine Gleisbox über einen CAN-Adapter</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::ConnectionStatus</name>
    <message>
        <source>Simulated CS2 (demo layout)</source>
        <translation>Simulierte CS2 (Demo-Anlage)</translation>
    </message>
    <message>
        <source>CS2 at %1 (UDP)</source>
        <translation>CS2 unter %1 (UDP)</translation>
    </message>
    <message>
        <source>CS2 at %1 (TCP)</source>
        <translation>CS2 unter %1 (TCP)</translation>
    </message>
    <message>
        <source>CAN interface %1</source>
        <translation>CAN-Schnittstelle %1</translation>
    </message>
    <message>
        <source>Station &quot;%1&quot;</source>
        <translation>Zentrale „%1“</translation>
    </message>
    <message>
        <source>No station connected</source>
        <translation>Keine Zentrale verbunden</translation>
    </message>
    <message>
        <source>%1 — connecting</source>
        <translation>%1 — Verbindung wird aufgebaut</translation>
    </message>
    <message>
        <source>%1 — ready: %2</source>
        <translation>%1 — bereit: %2</translation>
    </message>
    <message>
        <source>%1 — station silent</source>
        <translation>%1 — Zentrale antwortet nicht</translation>
    </message>
    <message>
        <source>%1 — failed: %2</source>
        <translation>%1 — fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>listing the devices</source>
        <translation>Geräte abfragen</translation>
    </message>
    <message>
        <source>waking up the Gleisbox</source>
        <translation>Gleisbox wecken</translation>
    </message>
    <message>
        <source>reading the devices</source>
        <translation>Gerätedaten lesen</translation>
    </message>
    <message>
        <source>files</source>
        <translation>Dateien</translation>
    </message>
    <message>
        <source>%1 %2 %</source>
        <translation>%1 %2 %</translation>
    </message>
    <message>
        <source>locomotive and contact states</source>
        <translation>Zustände der Loks und Rückmeldekontakte</translation>
    </message>
    <message>
        <source>%1, %2, %3</source>
        <translation>%1, %2, %3</translation>
    </message>
    <message numerus="yes">
        <source>%n locomotive(s)</source>
        <translation>
            <numerusform>%n Lok</numerusform>
            <numerusform>%n Loks</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n accessory(s)</source>
        <translation>
            <numerusform>%n Magnetartikel</numerusform>
            <numerusform>%n Magnetartikel</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n page(s)</source>
        <translation>
            <numerusform>%n Seite</numerusform>
            <numerusform>%n Seiten</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 — loading configuration %2/%3: %4</source>
        <translation>%1 — Konfiguration wird geladen %2/%3: %4</translation>
    </message>
    <message>
        <source>Try: restart Stellwerk; if it happens again, report the message above.</source>
        <translation>Versuchen Sie: Stellwerk neu starten; geschieht es wieder, die Meldung oben melden.</translation>
    </message>
    <message>
        <source>Try: check that the station is on and reachable at this address, and that its CAN-UDP gateway sends to this computer (CS2: Setup → IP → CAN gateway).</source>
        <translation>Versuchen Sie: prüfen, ob die Zentrale eingeschaltet und unter dieser Adresse erreichbar ist und ihr CAN-UDP-Gateway an diesen Rechner sendet (CS2: Einstellungen → IP → CAN-Gateway).</translation>
    </message>
    <message>
        <source>Try: check that the station is on and reachable at this address and port.</source>
        <translation>Versuchen Sie: prüfen, ob die Zentrale eingeschaltet und unter dieser Adresse und diesem Port erreichbar ist.</translation>
    </message>
    <message>
        <source>Try: check that the CAN interface exists and is up (SocketCAN: ip link set can0 up type can bitrate 250000) and that the Gleisbox has power.</source>
        <translation>Versuchen Sie: prüfen, ob die CAN-Schnittstelle existiert und aktiv ist (SocketCAN: ip link set can0 up type can bitrate 250000) und ob die Gleisbox Strom hat.</translation>
    </message>
    <message>
        <source>Try: correct the address in Station → Connect…, for example udp://192.168.2.5.</source>
        <translation>Versuchen Sie: die Adresse unter Zentrale → Verbinden … berichtigen, zum Beispiel udp://192.168.2.5.</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::ContactTableModel</name>
    <message>
        <source>Contact</source>
        <translation>Kontakt</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>Last change</source>
        <translation>Letzte Änderung</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <source>occupied</source>
        <translation>besetzt</translation>
    </message>
    <message>
        <source>free</source>
        <translation>frei</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Locomotive</source>
        <translation>Lok</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::CorrectionNotice</name>
    <message numerus="yes">
        <source>%n set back after trouble</source>
        <translation>
            <numerusform>%n nach Störung zurückgesetzt</numerusform>
            <numerusform>%n nach Störung zurückgesetzt</numerusform>
        </translation>
    </message>
    <message>
        <source>Dismiss</source>
        <translation>Verwerfen</translation>
    </message>
    <message>
        <source>Everything set back since the last Dismiss, with its time</source>
        <translation>Alles seit dem letzten „Verwerfen“ Zurückgesetzte, mit Uhrzeit</translation>
    </message>
    <message>
        <source>I have read it: hide this strip until something is set back again</source>
        <translation>Gelesen: diese Leiste ausblenden, bis wieder etwas zurückgesetzt wird</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::DeviceSettingEditor</name>
    <message>
        <source>writing…</source>
        <translation>wird geschrieben …</translation>
    </message>
    <message>
        <source>accepted ✓</source>
        <translation>übernommen ✓</translation>
    </message>
    <message>
        <source>refused ✗</source>
        <translation>abgelehnt ✗</translation>
    </message>
    <message>
        <source>no answer ✗</source>
        <translation>keine Antwort ✗</translation>
    </message>
    <message>
        <source>The device refused the value and keeps its setting.</source>
        <translation>Das Gerät hat den Wert abgelehnt und behält seine Einstellung.</translation>
    </message>
    <message>
        <source>The device did not answer; its setting is unknown. Try again.</source>
        <translation>Das Gerät hat nicht geantwortet; seine Einstellung ist unbekannt. Bitte erneut versuchen.</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::DeviceTableModel</name>
    <message>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Adresse</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>booster / system device</source>
        <translation>Booster / Systemgerät</translation>
    </message>
    <message>
        <source>throttle</source>
        <translation>Fahrpult</translation>
    </message>
    <message>
        <source>decoder</source>
        <translation>Dekoder</translation>
    </message>
    <message>
        <source>encoder</source>
        <translation>Enkoder</translation>
    </message>
    <message>
        <source>legacy decoder</source>
        <translation>Legacy-Dekoder</translation>
    </message>
    <message>
        <source>legacy encoder</source>
        <translation>Legacy-Enkoder</translation>
    </message>
    <message>
        <source>type %1</source>
        <translation>Typ %1</translation>
    </message>
    <message>
        <source>gone</source>
        <translation>verschwunden</translation>
    </message>
    <message>
        <source>OpenRailCAN %1</source>
        <translation>OpenRailCAN-%1</translation>
    </message>
    <message>
        <source>bus id %1</source>
        <translation>Bus-ID %1</translation>
    </message>
    <message>
        <source>getting its bus id</source>
        <translation>erhält seine Bus-ID</translation>
    </message>
    <message>
        <source>online</source>
        <translation>online</translation>
    </message>
    <message>
        <source>offline: misses its pings</source>
        <translation>offline: antwortet nicht auf Pings</translation>
    </message>
    <message>
        <source>refused: its bus id is taken</source>
        <translation>abgewiesen: seine Bus-ID ist vergeben</translation>
    </message>
    <message numerus="yes">
        <source>RO module, %n relay(s), %1-bit</source>
        <translation>
            <numerusform>RO-Modul, %n Relais, %1 Bit</numerusform>
            <numerusform>RO-Modul, %n Relais, %1 Bit</numerusform>
        </translation>
    </message>
    <message>
        <source>bus %1: %2 / %3</source>
        <translation>Bus %1: %2 / %3</translation>
    </message>
    <message>
        <source>refused</source>
        <translation>abgewiesen</translation>
    </message>
    <message>
        <source>bus not connected</source>
        <translation>Bus nicht verbunden</translation>
    </message>
    <message>
        <source>reading its relays</source>
        <translation>liest seine Relais</translation>
    </message>
    <message>
        <source>offline: does not answer</source>
        <translation>offline: antwortet nicht</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::DevicesPanel</name>
    <message>
        <source>Not connected.</source>
        <translation>Nicht verbunden.</translation>
    </message>
    <message>
        <source>OpenRailCAN: Stellwerk is not the central.</source>
        <translation>OpenRailCAN: Stellwerk ist nicht die Zentrale.</translation>
    </message>
    <message>
        <source>OpenRailCAN: its bus is not connected.</source>
        <translation>OpenRailCAN: sein Bus ist nicht verbunden.</translation>
    </message>
    <message numerus="yes">
        <source>OpenRailCAN: %1 of %n device(s) online.</source>
        <translation>
            <numerusform>OpenRailCAN: %1 von %n Gerät online.</numerusform>
            <numerusform>OpenRailCAN: %1 von %n Geräten online.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>RO modules: %1 of %n online.</source>
        <translation>
            <numerusform>RO-Module: %1 von %n online.</numerusform>
            <numerusform>RO-Module: %1 von %n online.</numerusform>
        </translation>
    </message>
    <message>
        <source>Refused: %1.</source>
        <translation>Abgewiesen: %1.</translation>
    </message>
    <message>
        <source>Modules you add or change are used from the next connection (Station ▸ Connect).</source>
        <translation>Hinzugefügte oder geänderte Module gelten ab der nächsten Verbindung (Zentrale ▸ Verbinden).</translation>
    </message>
    <message>
        <source>Remove RO module</source>
        <translation>RO-Modul entfernen</translation>
    </message>
    <message>
        <source>Remove the module &quot;%1&quot; from the station settings? Its bindings stay until you remove them.</source>
        <translation>Das Modul „%1“ aus den Einstellungen der Zentrale entfernen? Seine Zuordnungen bleiben, bis Sie sie entfernen.</translation>
    </message>
    <message>
        <source>Add RO module…</source>
        <translation>RO-Modul hinzufügen…</translation>
    </message>
    <message>
        <source>Change…</source>
        <translation>Ändern…</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Bindings…</source>
        <translation>Zuordnungen…</translation>
    </message>
    <message>
        <source>Choose a device to see its relays, outputs and inputs.</source>
        <translation>Wählen Sie ein Gerät, um seine Relais, Ausgänge und Eingänge zu sehen.</translation>
    </message>
    <message>
        <source>The demo station brings its own devices; modules you add are for your own station.</source>
        <translation>Die Demo-Zentrale bringt eigene Geräte mit; hinzugefügte Module gelten für Ihre eigene Zentrale.</translation>
    </message>
    <message>
        <source>The demo&apos;s bindings: what you change here lasts until you connect again.</source>
        <translation>Die Zuordnungen der Demo: Änderungen gelten bis zur nächsten Verbindung.</translation>
    </message>
    <message>
        <source>Saved with the station settings.</source>
        <translation>Wird mit den Einstellungen der Zentrale gespeichert.</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::FoundDecoders</name>
    <message>
        <source>mfx UID</source>
        <translation>mfx-UID</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
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
    <message>
        <source>Paste CAN frames of the CS2 or of MS1 handhelds (M-CAN), one per line, as written in the Märklin documents (00004711 5 00 00 00 00 00), by candump (00004711#0000000000) or as 13-byte network frames in hex. Lines starting with # are ignored; the lines are read in order, as one bus.</source>
        <translation>CAN-Telegramme der CS2 oder von MS1-Handgeräten (M-CAN) zeilenweise einfügen: wie in den Märklin-Dokumenten (00004711 5 00 00 00 00 00), wie von candump (00004711#0000000000) oder als 13-Byte-Netzwerktelegramm in Hex. Zeilen, die mit # beginnen, werden übergangen; die Zeilen werden der Reihe nach als ein Bus gelesen.</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::FunctionPad</name>
    <message>
        <source>on while held</source>
        <translation>an, solange gedrückt</translation>
    </message>
    <message numerus="yes">
        <source>on for %n s</source>
        <translation>
            <numerusform>%n s lang an</numerusform>
            <numerusform>%n s lang an</numerusform>
        </translation>
    </message>
    <message>
        <source>on/off</source>
        <translation>an/aus</translation>
    </message>
    <message>
        <source>F%1: %2 (%3)</source>
        <translation>F%1: %2 (%3)</translation>
    </message>
    <message>
        <source>The station did not acknowledge the last command: %1</source>
        <translation>Die Zentrale hat den letzten Befehl nicht bestätigt: %1</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::GaugeWidget</name>
    <message>
        <source>%1: no answer to the last request, the value is old</source>
        <translation>%1: keine Antwort auf die letzte Abfrage, der Wert ist alt</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::GuideBrowser</name>
    <message>
        <source>Stellwerk user guide</source>
        <translation>Stellwerk-Benutzerhandbuch</translation>
    </message>
    <message>
        <source>&amp;Back</source>
        <translation>&amp;Zurück</translation>
    </message>
    <message>
        <source>&amp;Contents</source>
        <translation>&amp;Inhalt</translation>
    </message>
    <message>
        <source>The user guide is not installed here. It is in the folder docs/guide of Stellwerk&apos;s sources, and after installing in share/doc/stellwerk/guide.</source>
        <translation>Das Benutzerhandbuch ist hier nicht installiert. Es liegt im Ordner docs/guide der Quellen von Stellwerk und nach der Installation in share/doc/stellwerk/guide.</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::HandheldDetails</name>
    <message>
        <source>Selected handheld</source>
        <translation>Gewähltes Handgerät</translation>
    </message>
    <message>
        <source>Name, up to 16 characters</source>
        <translation>Name, bis zu 16 Zeichen</translation>
    </message>
    <message>
        <source>Rename</source>
        <translation>Umbenennen</translation>
    </message>
    <message>
        <source>Send the name to the handheld; it shows it from now on</source>
        <translation>Den Namen an das Handgerät senden; es zeigt ihn von nun an</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Hinzufügen</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Up</source>
        <translation>Hoch</translation>
    </message>
    <message>
        <source>Down</source>
        <translation>Runter</translation>
    </message>
    <message>
        <source>The locomotives the handheld offers, in its order; remembered for this handheld</source>
        <translation>Die Loks, die das Handgerät anbietet, in seiner Reihenfolge; für dieses Handgerät gemerkt</translation>
    </message>
    <message>
        <source>Loc-ID 0x%1</source>
        <translation>Loc-ID 0x%1</translation>
    </message>
    <message>
        <source>The stack is full (%1 locomotives)</source>
        <translation>Der Lokstapel ist voll (%1 Loks)</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::HandheldTableModel</name>
    <message>
        <source>logging in (stage %1 of 7)</source>
        <translation>meldet sich an (Stufe %1 von 7)</translation>
    </message>
    <message>
        <source>reading its locomotives</source>
        <translation>liest seine Loks</translation>
    </message>
    <message>
        <source>online</source>
        <translation>angemeldet</translation>
    </message>
    <message>
        <source>online at another master</source>
        <translation>an einem anderen Master angemeldet</translation>
    </message>
    <message numerus="yes">
        <source>silent: %n poll(s) left</source>
        <translation>
            <numerusform>still: noch %n Abfrage</numerusform>
            <numerusform>still: noch %n Abfragen</numerusform>
        </translation>
    </message>
    <message>
        <source>silent</source>
        <translation>still</translation>
    </message>
    <message>
        <source>offline</source>
        <translation>abgemeldet</translation>
    </message>
    <message>
        <source>in its boot loader</source>
        <translation>im Bootloader</translation>
    </message>
    <message>
        <source>refused: somebody else drives it</source>
        <translation>abgelehnt: jemand anderes fährt sie</translation>
    </message>
    <message numerus="yes">
        <source>%n locomotive(s)</source>
        <translation>
            <numerusform>%n Lok</numerusform>
            <numerusform>%n Loks</numerusform>
        </translation>
    </message>
    <message>
        <source>UID %1</source>
        <translation>UID %1</translation>
    </message>
    <message>
        <source>Node %1; its master&apos;s node is %2</source>
        <translation>Knoten %1; der Knoten seines Masters ist %2</translation>
    </message>
    <message>
        <source>Handheld</source>
        <translation>Handgerät</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>Locomotive</source>
        <translation>Lok</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Fahrstufe</translation>
    </message>
    <message>
        <source>Functions</source>
        <translation>Funktionen</translation>
    </message>
    <message>
        <source>Stack</source>
        <translation>Lokstapel</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::HandheldsPanel</name>
    <message>
        <source>Not connected: no handhelds to show.</source>
        <translation>Nicht verbunden: keine Handgeräte.</translation>
    </message>
    <message>
        <source>Stellwerk is the master of the MS1 handhelds on this bus: plug one in to drive with it.</source>
        <translation>Stellwerk ist der Master der MS1-Handgeräte an diesem Bus: eine MS1 anstecken und damit fahren.</translation>
    </message>
    <message>
        <source>Stellwerk waits until it knows the devices on the bus before it answers any handheld.</source>
        <translation>Stellwerk antwortet Handgeräten erst, wenn es die Geräte am Bus kennt.</translation>
    </message>
    <message>
        <source>Stellwerk only watches the handhelds: the Central Station is their master.</source>
        <translation>Stellwerk beobachtet die Handgeräte nur: die Central Station ist ihr Master.</translation>
    </message>
    <message>
        <source>Stellwerk only watches the handhelds: another master (node %1) answers them.</source>
        <translation>Stellwerk beobachtet die Handgeräte nur: ein anderer Master (Knoten %1) antwortet ihnen.</translation>
    </message>
    <message>
        <source>Stellwerk only watches the handhelds, as chosen.</source>
        <translation>Stellwerk beobachtet die Handgeräte nur, wie eingestellt.</translation>
    </message>
    <message>
        <source>The handheld %1 sits in its boot loader: only a CS1 or an ECoS can flash it back to life. Stellwerk never sends it there and never flashes it.</source>
        <translation>Das Handgerät %1 steckt im Bootloader: nur eine CS1 oder ECoS kann es neu flashen. Stellwerk schickt es nie dorthin und flasht es nie.</translation>
    </message>
    <message>
        <source>Act as master for MS1 handhelds</source>
        <translation>Master für MS1-Handgeräte sein</translation>
    </message>
    <message>
        <source>Answer MS1 handhelds on the station&apos;s bus, unless a Central Station or another master does; off: only watch them</source>
        <translation>MS1-Handgeräten am Bus der Zentrale antworten, außer eine Central Station oder ein anderer Master tut es; aus: nur beobachten</translation>
    </message>
    <message>
        <source>Make it quiet</source>
        <translation>Zum Schweigen bringen</translation>
    </message>
    <message>
        <source>Tell it to stop sending; it stays in its boot loader</source>
        <translation>Es soll aufhören zu senden; es bleibt im Bootloader</translation>
    </message>
    <message>
        <source>Stellwerk only watches the handhelds: another master answers them.</source>
        <translation>Stellwerk beobachtet die Handgeräte nur: ein anderer Master antwortet ihnen.</translation>
    </message>
    <message>
        <source>Another master answers the handhelds on this bus: Stellwerk only watches them</source>
        <translation>Ein anderer Master antwortet den Handgeräten auf diesem Bus: Stellwerk beobachtet sie nur</translation>
    </message>
    <message>
        <source>MS1 handhelds (%1)</source>
        <translation>MS1-Handgeräte (%1)</translation>
    </message>
    <message>
        <source>Phones and other throttles (%1)</source>
        <translation>Handys und andere Handregler (%1)</translation>
    </message>
    <message>
        <source>Phones of the Z21 app and WLANmaus, Engine Driver and WiThrottle, and OpenRailCAN throttles. Select a phone to disconnect it.</source>
        <translation>Handys mit der Z21-App, WLANmäuse, Engine Driver und WiThrottle sowie OpenRailCAN-Handregler. Ein Handy auswählen, um es zu trennen.</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>Trennen</translation>
    </message>
    <message>
        <source>Let the selected phone go: its locomotives are stopped</source>
        <translation>Das ausgewählte Handy trennen: seine Loks werden angehalten</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::KeyList</name>
    <message>
        <source>Keys</source>
        <translation>Tasten</translation>
    </message>
    <message>
        <source>What they do</source>
        <translation>Was sie tun</translation>
    </message>
    <message>
        <source>Space</source>
        <translation>Leertaste</translation>
    </message>
    <message>
        <source>Alt+1 … Alt+9</source>
        <translation>Alt+1 … Alt+9</translation>
    </message>
    <message>
        <source>Put the keyboard on throttle 1 … 9</source>
        <translation>Tastatur auf Fahrpult 1 … 9 legen</translation>
    </message>
    <message>
        <source>Up, Down, +, −</source>
        <translation>Pfeil auf, Pfeil ab, +, −</translation>
    </message>
    <message>
        <source>On a throttle: faster, slower</source>
        <translation>Am Fahrpult: schneller, langsamer</translation>
    </message>
    <message>
        <source>On a throttle: much faster, much slower</source>
        <translation>Am Fahrpult: viel schneller, viel langsamer</translation>
    </message>
    <message>
        <source>R</source>
        <translation>R</translation>
    </message>
    <message>
        <source>On a throttle: change direction</source>
        <translation>Am Fahrpult: Richtung wechseln</translation>
    </message>
    <message>
        <source>0 … 9</source>
        <translation>0 … 9</translation>
    </message>
    <message>
        <source>On a throttle: functions F0 … F9</source>
        <translation>Am Fahrpult: Funktionen F0 … F9</translation>
    </message>
    <message>
        <source>E</source>
        <translation>E</translation>
    </message>
    <message>
        <source>On a throttle: stop this locomotive</source>
        <translation>Am Fahrpult: diese Lok anhalten</translation>
    </message>
    <message>
        <source>STOP: track power off for the whole layout, from anywhere (also while a throttle has the keys)</source>
        <translation>STOPP: Gleisspannung für die ganze Anlage aus, von überall (auch wenn ein Fahrpult die Tastatur hat)</translation>
    </message>
    <message>
        <source>STOP, the extra STOP key (choose another under Station → Extra STOP key)</source>
        <translation>STOPP, die zusätzliche STOPP-Taste (eine andere unter Zentrale → Zusätzliche STOPP-Taste wählen)</translation>
    </message>
    <message>
        <source>Turnout keyboard: previous page, next page</source>
        <translation>Keyboard: vorige Seite, nächste Seite</translation>
    </message>
    <message>
        <source>Turnout keyboard: switch the key that has the focus</source>
        <translation>Keyboard: die Taste mit dem Fokus schalten</translation>
    </message>
    <message>
        <source>Locomotives: save the changes to a folder</source>
        <translation>Loks: die Änderungen in einen Ordner speichern</translation>
    </message>
    <message>
        <source>Locomotives: remove the selected locomotive</source>
        <translation>Loks: die gewählte Lok entfernen</translation>
    </message>
    <message>
        <source>Bus monitor: %1</source>
        <translation>Busmonitor: %1</translation>
    </message>
    <message>
        <source>On the bare window (nothing open on top): STOP, track power off for the whole layout</source>
        <translation>Im Hauptfenster (nichts darüber geöffnet): STOPP, Gleisspannung für die ganze Anlage aus</translation>
    </message>
    <message>
        <source>In a dialog, menu or popup: closes it, and nothing else</source>
        <translation>In einem Dialog, Menü oder Popup: schließt es, sonst nichts</translation>
    </message>
    <message>
        <source>Locomotives: change the selected locomotive&apos;s Z21 address</source>
        <translation>Loks: die Z21-Adresse der gewählten Lok ändern</translation>
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
    <name>stellwerk::ui::LayoutFileActions</name>
    <message>
        <source>Layout exported</source>
        <translation>Gleisbild exportiert</translation>
    </message>
    <message>
        <source>The layout was written to %1 as a CS2 configuration folder.</source>
        <translation>Das Gleisbild wurde als CS2-Konfigurationsordner nach %1 geschrieben.</translation>
    </message>
    <message>
        <source>No layouts opened yet</source>
        <translation>Noch keine Gleisbilder geöffnet</translation>
    </message>
    <message>
        <source>Clear the list</source>
        <translation>Liste leeren</translation>
    </message>
    <message>
        <source>Open &amp;recent layout</source>
        <translation>&amp;Zuletzt geöffnete Gleisbilder</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::LayoutFileDialog</name>
    <message>
        <source>Open a CS2 layout folder or track plan page</source>
        <translation>CS2-Gleisbildordner oder Gleisbildseite öffnen</translation>
    </message>
    <message>
        <source>CS2 track plan files (*.cs2)</source>
        <translation>CS2-Gleisbilddateien (*.cs2)</translation>
    </message>
    <message>
        <source>Export the layout into a folder</source>
        <translation>Gleisbild in einen Ordner exportieren</translation>
    </message>
    <message>
        <source>The folder %1 cannot be made here. Choose another place.</source>
        <translation>Der Ordner %1 lässt sich hier nicht anlegen. Wählen Sie einen anderen Ort.</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::LayoutOverview</name>
    <message>
        <source>Locomotives</source>
        <translation>Loks</translation>
    </message>
    <message>
        <source>Feedback contacts</source>
        <translation>Rückmeldekontakte</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::LayoutStateBanner</name>
    <message>
        <source>Not reported: the station is silent or being reconnected. Greyed states are the last it reported.</source>
        <translation>Nicht gemeldet: Die Zentrale antwortet nicht oder wird neu verbunden. Grau Dargestelltes ist der zuletzt gemeldete Zustand.</translation>
    </message>
    <message>
        <source>Track power not reported yet: the station has not said whether trains may run.</source>
        <translation>Gleisspannung noch nicht gemeldet: Die Zentrale hat nicht gesagt, ob Züge fahren dürfen.</translation>
    </message>
    <message>
        <source>LAYOUT STOPPED: track power is off. Press the power key in the toolbar to switch it on.</source>
        <translation>ANLAGE GESTOPPT: Die Gleisspannung ist aus. Zum Einschalten die Stromtaste in der Werkzeugleiste drücken.</translation>
    </message>
    <message>
        <source>LAYOUT HALTED: every train was halted. Press the power key in the toolbar to go on.</source>
        <translation>ANLAGE ANGEHALTEN: Alle Züge wurden angehalten. Zum Weiterfahren die Stromtaste in der Werkzeugleiste drücken.</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::LocomotiveFileModel</name>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Adresse</translation>
    </message>
    <message>
        <source>Decoder</source>
        <translation>Decoder</translation>
    </message>
    <message>
        <source>Icon</source>
        <translation>Bild</translation>
    </message>
    <message>
        <source>Functions</source>
        <translation>Funktionen</translation>
    </message>
    <message>
        <source>MM2 (programmable)</source>
        <translation>MM2 (programmierbar)</translation>
    </message>
    <message>
        <source>MM2 (DIL switches)</source>
        <translation>MM2 (DIL-Schalter)</translation>
    </message>
    <message>
        <source>MM (programmable)</source>
        <translation>MM (programmierbar)</translation>
    </message>
    <message>
        <source>MM2 (mLD/mSD)</source>
        <translation>MM2 (mLD/mSD)</translation>
    </message>
    <message>
        <source>DCC</source>
        <translation>DCC</translation>
    </message>
    <message>
        <source>mfx</source>
        <translation>mfx</translation>
    </message>
    <message>
        <source>SX1</source>
        <translation>SX1</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keiner</translation>
    </message>
    <message>
        <source>DCC %1</source>
        <translation>DCC %1</translation>
    </message>
    <message>
        <source>mfx SID %1</source>
        <translation>mfx SID %1</translation>
    </message>
    <message>
        <source>SX1 %1</source>
        <translation>SX1 %1</translation>
    </message>
    <message>
        <source>MM2 %1</source>
        <translation>MM2 %1</translation>
    </message>
    <message>
        <source>The address the Z21 app and WLANmaus use for this locomotive; double-click to change it</source>
        <translation>Die Adresse, unter der die Z21-App und die WLANmaus diese Lok kennen; zum Ändern doppelklicken</translation>
    </message>
    <message>
        <source>A DCC locomotive has its own address on the Z21 too</source>
        <translation>Eine DCC-Lok hat auch an der Z21 ihre eigene Adresse</translation>
    </message>
    <message>
        <source>Z21 address</source>
        <translation>Z21-Adresse</translation>
    </message>
    <message>
        <source>A Z21 address is a number from %1 to %2; &apos;%3&apos; keeps %4.</source>
        <translation>Eine Z21-Adresse ist eine Zahl von %1 bis %2; &apos;%3&apos; behält %4.</translation>
    </message>
    <message>
        <source>Z21 address %1 is kept for another locomotive; &apos;%2&apos; keeps %3.</source>
        <translation>Die Z21-Adresse %1 ist für eine andere Lok vergeben; &apos;%2&apos; behält %3.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; already has Z21 address %2; &apos;%3&apos; keeps %4.</source>
        <translation>&apos;%1&apos; hat schon die Z21-Adresse %2; &apos;%3&apos; behält %4.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has Z21 address %2 now.</source>
        <translation>&apos;%1&apos; hat jetzt die Z21-Adresse %2.</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::LocomotiveForm</name>
    <message>
        <source>allowed: %1–%2</source>
        <translation>erlaubt: %1–%2</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Name:</translation>
    </message>
    <message>
        <source>Decoder:</source>
        <translation>Decoder:</translation>
    </message>
    <message>
        <source>Address:</source>
        <translation>Adresse:</translation>
    </message>
    <message>
        <source>Icon</source>
        <translation>Symbol</translation>
    </message>
    <message>
        <source>Trigger</source>
        <translation>Schaltart</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>latching</source>
        <translation>Dauerfunktion</translation>
    </message>
    <message>
        <source>momentary</source>
        <translation>Momentfunktion</translation>
    </message>
    <message>
        <source>timed</source>
        <translation>Zeitfunktion</translation>
    </message>
    <message>
        <source>as in the file</source>
        <translation>wie in der Datei</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keins</translation>
    </message>
    <message>
        <source>Shows</source>
        <translation>Zeigt</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::LocomotivePanel</name>
    <message>
        <source>New locomotive</source>
        <translation>Neue Lok</translation>
    </message>
    <message>
        <source>Enter the new locomotive and press Add.</source>
        <translation>Die neue Lok eintragen und „Hinzufügen“ drücken.</translation>
    </message>
    <message>
        <source>Changed. Save to write lokomotive.cs2.</source>
        <translation>Geändert. Speichern schreibt lokomotive.cs2.</translation>
    </message>
    <message>
        <source>Deleted. Save to write lokomotive.cs2.</source>
        <translation>Gelöscht. Speichern schreibt lokomotive.cs2.</translation>
    </message>
    <message>
        <source>Delete locomotive</source>
        <translation>Lok löschen</translation>
    </message>
    <message>
        <source>Delete &apos;%1&apos; from the locomotive list?</source>
        <translation>„%1“ aus der Lokliste löschen?</translation>
    </message>
    <message>
        <source>The new mfx decoder is in the list as &apos;%1&apos;. Save to write lokomotive.cs2.</source>
        <translation>Der neue mfx-Decoder steht als „%1“ in der Liste. Speichern schreibt lokomotive.cs2.</translation>
    </message>
    <message>
        <source>Save lokomotive.cs2 into a CS2 configuration folder</source>
        <translation>lokomotive.cs2 in einen CS2-Konfigurationsordner speichern</translation>
    </message>
    <message>
        <source>Not saved: %1. The edits are kept.</source>
        <translation>Nicht gespeichert: %1. Die Änderungen bleiben erhalten.</translation>
    </message>
    <message>
        <source>Saved to %1.</source>
        <translation>In %1 gespeichert.</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Hinzufügen</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Übernehmen</translation>
    </message>
    <message>
        <source>Locomotives</source>
        <translation>Loks</translation>
    </message>
    <message numerus="yes">
        <source>%n locomotive(s), changed and not saved</source>
        <translation>
            <numerusform>%n Lok, geändert und nicht gespeichert</numerusform>
            <numerusform>%n Loks, geändert und nicht gespeichert</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n locomotive(s)</source>
        <translation>
            <numerusform>%n Lok</numerusform>
            <numerusform>%n Loks</numerusform>
        </translation>
    </message>
    <message>
        <source>Give the locomotive a name.</source>
        <translation>Bitte der Lok einen Namen geben.</translation>
    </message>
    <message>
        <source>The name must be on one line.</source>
        <translation>Der Name darf nur eine Zeile lang sein.</translation>
    </message>
    <message>
        <source>Another locomotive is already called &apos;%1&apos;.</source>
        <translation>Eine andere Lok heißt bereits „%1“.</translation>
    </message>
    <message>
        <source>Choose the decoder type.</source>
        <translation>Bitte den Decodertyp wählen.</translation>
    </message>
    <message>
        <source>The address must be between %1 and %2 for this decoder.</source>
        <translation>Die Adresse muss für diesen Decoder zwischen %1 und %2 liegen.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; already uses this address.</source>
        <translation>„%1“ verwendet diese Adresse bereits.</translation>
    </message>
    <message>
        <source>F%1 is not a function key (F0 to F31).</source>
        <translation>F%1 ist keine Funktionstaste (F0 bis F31).</translation>
    </message>
    <message>
        <source>The icon of F%1 must be between %2 and %3.</source>
        <translation>Das Symbol von F%1 muss zwischen %2 und %3 liegen.</translation>
    </message>
    <message>
        <source>The time of F%1 must be between %2 and %3.</source>
        <translation>Die Zeit von F%1 muss zwischen %2 und %3 liegen.</translation>
    </message>
    <message>
        <source>Select a locomotive first.</source>
        <translation>Bitte zuerst eine Lok auswählen.</translation>
    </message>
    <message>
        <source>No station connected.</source>
        <translation>Keine Zentrale verbunden.</translation>
    </message>
    <message>
        <source>The station has not sent its locomotive list (lokomotive.cs2).</source>
        <translation>Die Zentrale hat ihre Lokliste (lokomotive.cs2) nicht gesendet.</translation>
    </message>
    <message>
        <source>New</source>
        <translation>Neu</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <source>Save to folder…</source>
        <translation>In Ordner speichern …</translation>
    </message>
    <message>
        <source>Writes config/lokomotive.cs2 into the folder you choose</source>
        <translation>Schreibt config/lokomotive.cs2 in den gewählten Ordner</translation>
    </message>
    <message>
        <source>Revert</source>
        <translation>Verwerfen</translation>
    </message>
    <message>
        <source>The station sent its locomotive list again; your unsaved changes are kept.</source>
        <translation>Die Zentrale hat ihre Lokliste erneut gesendet; Ihre nicht gespeicherten Änderungen bleiben erhalten.</translation>
    </message>
    <message>
        <source>Unsaved locomotive changes</source>
        <translation>Nicht gespeicherte Lok-Änderungen</translation>
    </message>
    <message>
        <source>The locomotive list has changes that are not saved. Save them before %1?</source>
        <translation>Die Lokliste hat Änderungen, die nicht gespeichert sind. Vor %1 speichern?</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::LocomotivePictureBook</name>
    <message>
        <source>No picture: no station</source>
        <translation>Kein Bild: keine Zentrale</translation>
    </message>
    <message>
        <source>This locomotive names no picture</source>
        <translation>Diese Lok nennt kein Bild</translation>
    </message>
    <message>
        <source>The picture “%1” is damaged</source>
        <translation>Das Bild „%1“ ist beschädigt</translation>
    </message>
    <message>
        <source>Picture “%1”</source>
        <translation>Bild „%1“</translation>
    </message>
    <message>
        <source>Loading the picture “%1”…</source>
        <translation>Bild „%1“ wird geladen …</translation>
    </message>
    <message>
        <source>No picture “%1”: %2</source>
        <translation>Kein Bild „%1“: %2</translation>
    </message>
    <message>
        <source>not a usable file name</source>
        <translation>kein brauchbarer Dateiname</translation>
    </message>
    <message>
        <source>no station to ask and no icons folder</source>
        <translation>keine Zentrale zum Fragen und kein Bilderordner</translation>
    </message>
    <message>
        <source>the station has none</source>
        <translation>die Zentrale hat keins</translation>
    </message>
    <message>
        <source>the file is not a usable PNG picture</source>
        <translation>die Datei ist kein brauchbares PNG-Bild</translation>
    </message>
    <message>
        <source>the station did not send it; asked again when it is back</source>
        <translation>die Zentrale hat es nicht geschickt; neue Anfrage, sobald sie wieder da ist</translation>
    </message>
    <message>
        <source>not known yet</source>
        <translation>noch nicht bekannt</translation>
    </message>
    <message>
        <source>Looked for at %1</source>
        <translation>Gesucht unter %1</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::LocomotiveTableModel</name>
    <message>
        <source>Locomotive</source>
        <translation>Lok</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Adresse</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>Direction</source>
        <translation>Richtung</translation>
    </message>
    <message>
        <source>Functions on</source>
        <translation>Funktionen an</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>backward</source>
        <translation>rückwärts</translation>
    </message>
    <message>
        <source>forward</source>
        <translation>vorwärts</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
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
        <source>The translation &quot;%1&quot; could not be loaded.</source>
        <translation>Die Übersetzung „%1“ konnte nicht geladen werden.</translation>
    </message>
    <message>
        <source>Frame decoder</source>
        <translation>Telegramm-Decoder</translation>
    </message>
    <message>
        <source>&amp;Station</source>
        <translation>&amp;Zentrale</translation>
    </message>
    <message>
        <source>&amp;Connect…</source>
        <translation>&amp;Verbinden …</translation>
    </message>
    <message>
        <source>Choose the station to connect to, or the simulated one</source>
        <translation>Die Zentrale wählen, mit der Stellwerk sich verbindet, oder die simulierte</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Bus monitor</source>
        <translation>Busmonitor</translation>
    </message>
    <message>
        <source>&amp;Stop everything</source>
        <translation>Alles &amp;anhalten</translation>
    </message>
    <message>
        <source>Switch the track power off: every train stops</source>
        <translation>Gleisspannung ausschalten: alle Züge halten</translation>
    </message>
    <message>
        <source>Stop and go</source>
        <translation>Stopp und Go</translation>
    </message>
    <message>
        <source>&amp;Panels</source>
        <translation>&amp;Bereiche</translation>
    </message>
    <message>
        <source>&amp;Reset panel layout</source>
        <translation>Anordnung der Bereiche &amp;zurücksetzen</translation>
    </message>
    <message>
        <source>Put every panel back where it was at the first start</source>
        <translation>Jeden Bereich wieder dorthin stellen, wo er beim ersten Start war</translation>
    </message>
    <message>
        <source>Keyboard</source>
        <translation>Keyboard</translation>
    </message>
    <message>
        <source>Throttles</source>
        <translation>Fahrpulte</translation>
    </message>
    <message>
        <source>Locomotives</source>
        <translation>Loks</translation>
    </message>
    <message>
        <source>Programming</source>
        <translation>Programmierung</translation>
    </message>
    <message>
        <source>Overview</source>
        <translation>Übersicht</translation>
    </message>
    <message>
        <source>quitting</source>
        <translation>dem Beenden</translation>
    </message>
    <message>
        <source>opening another layout</source>
        <translation>dem Öffnen einer anderen Anlage</translation>
    </message>
    <message>
        <source>connecting again</source>
        <translation>dem erneuten Verbinden</translation>
    </message>
    <message>
        <source>Space</source>
        <translation>Leertaste</translation>
    </message>
    <message>
        <source>Space, %1</source>
        <translation>Leertaste, %1</translation>
    </message>
    <message>
        <source>User &amp;guide</source>
        <translation>&amp;Benutzerhandbuch</translation>
    </message>
    <message>
        <source>Read how to use Stellwerk</source>
        <translation>Lesen, wie Stellwerk bedient wird</translation>
    </message>
    <message>
        <source>&amp;Keys</source>
        <translation>&amp;Tasten</translation>
    </message>
    <message>
        <source>Every key the desk answers to</source>
        <translation>Alle Tasten, auf die das Stellpult reagiert</translation>
    </message>
    <message>
        <source>Devices</source>
        <translation>Geräte</translation>
    </message>
    <message>
        <source>Set back after trouble</source>
        <translation>Nach Störung zurückgesetzt</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automatik</translation>
    </message>
    <message>
        <source>&amp;Phones and Tablets…</source>
        <translation>&amp;Handys und Tablets…</translation>
    </message>
    <message>
        <source>Let the Z21 app, a WLANmaus, Engine Driver or WiThrottle drive the layout</source>
        <translation>Die Anlage mit der Z21-App, einer WLANmaus, Engine Driver oder WiThrottle fahren</translation>
    </message>
    <message>
        <source>Handhelds and phones</source>
        <translation>Handregler und Handys</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::OrcDeviceView</name>
    <message>
        <source>OpenRailCAN device %1</source>
        <translation>OpenRailCAN-Gerät %1</translation>
    </message>
    <message>
        <source>Inputs</source>
        <translation>Eingänge</translation>
    </message>
    <message>
        <source>Outputs as the decoder last confirmed them (%1 until it confirms a switch)</source>
        <translation>Ausgänge, wie der Dekoder sie zuletzt bestätigt hat (%1, bis er eine Schaltung bestätigt)</translation>
    </message>
    <message>
        <source>The central no longer knows this device.</source>
        <translation>Die Zentrale kennt dieses Gerät nicht mehr.</translation>
    </message>
    <message>
        <source>%1, bus id %2, version %3.%4</source>
        <translation>%1, Bus-ID %2, Version %3.%4</translation>
    </message>
    <message>
        <source>Getting its bus id from the central.</source>
        <translation>Erhält seine Bus-ID von der Zentrale.</translation>
    </message>
    <message>
        <source>Online: answers the central&apos;s pings.</source>
        <translation>Online: antwortet auf die Pings der Zentrale.</translation>
    </message>
    <message numerus="yes">
        <source>Offline: missed %n ping(s); what it reported is %1.</source>
        <translation>
            <numerusform>Offline: %n Ping verpasst; was es gemeldet hat, ist %1.</numerusform>
            <numerusform>Offline: %n Pings verpasst; was es gemeldet hat, ist %1.</numerusform>
        </translation>
    </message>
    <message>
        <source>Refused: another device has its bus id and it did not take a new one.</source>
        <translation>Abgewiesen: ein anderes Gerät hat seine Bus-ID, und es hat keine neue angenommen.</translation>
    </message>
    <message>
        <source>the whole device</source>
        <translation>das ganze Gerät</translation>
    </message>
    <message>
        <source>output %1</source>
        <translation>Ausgang %1</translation>
    </message>
    <message>
        <source>No overload.</source>
        <translation>Keine Überlast.</translation>
    </message>
    <message>
        <source>OVERLOAD: %1</source>
        <translation>ÜBERLAST: %1</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::OtherThrottles</name>
    <message>
        <source>CAN bus</source>
        <translation>CAN-Bus</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::PhoneStatus</name>
    <message>
        <source>Phones: %1</source>
        <translation>Handys: %1</translation>
    </message>
    <message>
        <source>No phone or tablet is connected.</source>
        <translation>Kein Handy und kein Tablet ist verbunden.</translation>
    </message>
    <message>
        <source>Connected:
%1</source>
        <translation>Verbunden:
%1</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::PhonesDialog</name>
    <message>
        <source>Phones and Tablets</source>
        <translation>Handys und Tablets</translation>
    </message>
    <message>
        <source>Phones and tablets drive the layout as throttles: the Z21 app and the WLANmaus through the Z21 server, Engine Driver and WiThrottle through the WiThrottle server.</source>
        <translation>Handys und Tablets fahren die Anlage als Handregler: die Z21-App und die WLANmaus über den Z21-Server, Engine Driver und WiThrottle über den WiThrottle-Server.</translation>
    </message>
    <message>
        <source>Z21 server (Z21 app, WLANmaus)</source>
        <translation>Z21-Server (Z21-App, WLANmaus)</translation>
    </message>
    <message>
        <source>WiThrottle server (Engine Driver, WiThrottle)</source>
        <translation>WiThrottle-Server (Engine Driver, WiThrottle)</translation>
    </message>
    <message>
        <source>every phone in the network</source>
        <translation>jedes Handy im Netz</translation>
    </message>
    <message>
        <source>Only these phones (addresses):</source>
        <translation>Nur diese Handys (Adressen):</translation>
    </message>
    <message>
        <source>all network interfaces</source>
        <translation>alle Netzwerkschnittstellen</translation>
    </message>
    <message>
        <source>Listen on address:</source>
        <translation>Auf Adresse hören:</translation>
    </message>
    <message>
        <source>Port:</source>
        <translation>Port:</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a network address of this computer (for example 192.168.1.20); leave it empty to listen on all of them.</source>
        <translation>„%1“ ist keine Netzwerkadresse dieses Computers (zum Beispiel 192.168.1.20); leer lassen, um auf allen zu hören.</translation>
    </message>
    <message>
        <source>The allowed phones must be network addresses, separated by commas (for example 192.168.1.30, 192.168.1.31).</source>
        <translation>Die erlaubten Handys müssen Netzwerkadressen sein, durch Kommas getrennt (zum Beispiel 192.168.1.30, 192.168.1.31).</translation>
    </message>
    <message>
        <source>Could not start: %1. Another program may use the port; choose another one.</source>
        <translation>Konnte nicht starten: %1. Vielleicht nutzt ein anderes Programm den Port; bitte einen anderen wählen.</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::PlaceTrainDialog</name>
    <message>
        <source>End %1, %2</source>
        <translation>Ende %1, %2</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Locomotive:</source>
        <translation>Lok:</translation>
    </message>
    <message>
        <source>Length:</source>
        <translation>Länge:</translation>
    </message>
    <message>
        <source>Place</source>
        <translation>Aufgleisen</translation>
    </message>
    <message>
        <source>The train is tracked from here on: put it on the track in %1 first.</source>
        <translation>Der Zug wird ab hier verfolgt: stellen Sie ihn zuerst in %1 auf das Gleis.</translation>
    </message>
    <message>
        <source>towards %1</source>
        <translation>Richtung %1</translation>
    </message>
    <message>
        <source> or </source>
        <translation> oder </translation>
    </message>
    <message>
        <source>towards a buffer stop</source>
        <translation>Richtung Prellbock</translation>
    </message>
    <message>
        <source>towards a turntable</source>
        <translation>Richtung Drehscheibe</translation>
    </message>
    <message>
        <source>towards the end of the track</source>
        <translation>Richtung Gleisende</translation>
    </message>
    <message>
        <source>Place a train</source>
        <translation>Zug aufgleisen</translation>
    </message>
    <message>
        <source>May change direction in any block (push-pull)</source>
        <translation>Darf in jedem Block die Richtung wechseln (Wendezug)</translation>
    </message>
    <message>
        <source>Block:</source>
        <translation>Block:</translation>
    </message>
    <message>
        <source>Its front faces:</source>
        <translation>Seine Spitze zeigt zu:</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::PlanAutomation</name>
    <message>
        <source>for %1</source>
        <comment>a block reserved for a train</comment>
        <translation>für %1</translation>
    </message>
    <message>
        <source>unknown occupant</source>
        <translation>unbekannt belegt</translation>
    </message>
    <message>
        <source>%1 · fault</source>
        <comment>a train stopped by a fault</comment>
        <translation>%1 · Störung</translation>
    </message>
    <message>
        <source>Automation: free</source>
        <translation>Automatik: frei</translation>
    </message>
    <message>
        <source>Automation: reserved for %1 (hatched)</source>
        <translation>Automatik: reserviert für %1 (schraffiert)</translation>
    </message>
    <message>
        <source>Automation: %1 is in this block (solid)</source>
        <translation>Automatik: %1 steht in diesem Block (gefüllt)</translation>
    </message>
    <message>
        <source>Automation: an unknown occupant, no train can have reached it (cross-hatched); no automatic train enters it</source>
        <translation>Automatik: unbekannt belegt, kein Zug kann ihn erreicht haben (kreuzschraffiert); kein automatischer Zug fährt hinein</translation>
    </message>
    <message>
        <source>Automation: %1 stopped by a fault (dotted); see the Automatic panel</source>
        <translation>Automatik: %1 wegen einer Störung angehalten (gepunktet); siehe Seite „Automatik“</translation>
    </message>
    <message>
        <source>No automation runs on this layout.</source>
        <translation>Auf dieser Anlage läuft keine Automatik.</translation>
    </message>
    <message>
        <source>The block is reserved for %1: choose another block.</source>
        <translation>Der Block ist für %1 reserviert: wählen Sie einen anderen Block.</translation>
    </message>
    <message>
        <source>%1 is in this block already: remove it first.</source>
        <translation>%1 steht schon in diesem Block: nehmen Sie ihn zuerst heraus.</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::PowerStatus</name>
    <message>
        <source>No station connected</source>
        <translation>Keine Zentrale verbunden</translation>
    </message>
    <message>
        <source>Track power: not reported yet</source>
        <translation>Gleisspannung: noch nicht gemeldet</translation>
    </message>
    <message>
        <source>Track power: on, trains may run</source>
        <translation>Gleisspannung: an, Züge dürfen fahren</translation>
    </message>
    <message>
        <source>Track power: on, every train halted</source>
        <translation>Gleisspannung: an, alle Züge angehalten</translation>
    </message>
    <message>
        <source>Track power: off (stop)</source>
        <translation>Gleisspannung: aus (Stopp)</translation>
    </message>
    <message>
        <source>Track power: not reported</source>
        <translation>Gleisspannung: nicht gemeldet</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::ProblemBar</name>
    <message>
        <source>Show all</source>
        <translation>Alles zeigen</translation>
    </message>
    <message>
        <source>Fold</source>
        <translation>Einklappen</translation>
    </message>
    <message>
        <source>Show the whole message</source>
        <translation>Die ganze Meldung zeigen</translation>
    </message>
    <message>
        <source>Show only the first line</source>
        <translation>Nur die erste Zeile zeigen</translation>
    </message>
    <message>
        <source>Dismiss this message</source>
        <translation>Diese Meldung schließen</translation>
    </message>
    <message>
        <source>Dismiss</source>
        <translation>Schließen</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::ProgrammingPanel</name>
    <message>
        <source>(address below)</source>
        <translation>(Adresse unten)</translation>
    </message>
    <message>
        <source>MM2 decoders can be written (CV 1–256) but not read back.</source>
        <translation>MM2-Decoder lassen sich schreiben (CV 1–256), aber nicht auslesen.</translation>
    </message>
    <message>
        <source>mfx: CV 1–1023 with an index (read 0–63, write 1–63), on either track.</source>
        <translation>mfx: CV 1–1023 mit Index (lesen 0–63, schreiben 1–63), auf Haupt- und Programmiergleis.</translation>
    </message>
    <message>
        <source>SX1: values 1–5 (address, top speed, acceleration, pulse width, stop sections), programming track only.</source>
        <translation>SX1: Werte 1–5 (Adresse, Höchstgeschwindigkeit, Beschleunigung, Impulsbreite, Halteabschnitte), nur auf dem Programmiergleis.</translation>
    </message>
    <message>
        <source>DCC: CV 1–1023; read on the programming track, write on either track.</source>
        <translation>DCC: CV 1–1023; lesen auf dem Programmiergleis, schreiben auf Haupt- und Programmiergleis.</translation>
    </message>
    <message>
        <source>Searching the track for new mfx decoders…</source>
        <translation>Neue mfx-Decoder auf dem Gleis werden gesucht …</translation>
    </message>
    <message>
        <source>Searching: %1 of %2 bits of the decoder&apos;s UID known (%3)</source>
        <translation>Suche: %1 von %2 Bits der Decoder-UID bekannt (%3)</translation>
    </message>
    <message>
        <source>This address does not exist for the chosen protocol.</source>
        <translation>Diese Adresse gibt es im gewählten Protokoll nicht.</translation>
    </message>
    <message>
        <source>Reading CV %1…</source>
        <translation>CV %1 wird gelesen …</translation>
    </message>
    <message>
        <source>Writing CV %1…</source>
        <translation>CV %1 wird geschrieben …</translation>
    </message>
    <message>
        <source>No new mfx decoder answered. Decoders that are registered already take no part.</source>
        <translation>Kein neuer mfx-Decoder hat geantwortet. Bereits angemeldete Decoder nehmen an der Suche nicht teil.</translation>
    </message>
    <message>
        <source>found</source>
        <translation>gefunden</translation>
    </message>
    <message>
        <source>Found mfx decoder %1. Choose a SID and press Register; search again for more.</source>
        <translation>mfx-Decoder %1 gefunden. Eine SID wählen und „Anmelden“ drücken; für weitere erneut suchen.</translation>
    </message>
    <message>
        <source>bound to SID %1, verifying…</source>
        <translation>an SID %1 gebunden, wird geprüft …</translation>
    </message>
    <message>
        <source>does not answer under SID %1</source>
        <translation>antwortet nicht unter SID %1</translation>
    </message>
    <message>
        <source>registered on SID %1</source>
        <translation>unter SID %1 angemeldet</translation>
    </message>
    <message>
        <source>CV %1.%2</source>
        <translation>CV %1.%2</translation>
    </message>
    <message>
        <source>CV %1</source>
        <translation>CV %1</translation>
    </message>
    <message>
        <source>%1 = %2 (0x%3)</source>
        <translation>%1 = %2 (0x%3)</translation>
    </message>
    <message>
        <source>%1 written: %2, read back and verified.</source>
        <translation>%1 geschrieben: %2, zurückgelesen und geprüft.</translation>
    </message>
    <message>
        <source>%1 written: %2. Not verified: the decoder cannot be read back.</source>
        <translation>%1 geschrieben: %2. Nicht geprüft: Der Decoder lässt sich nicht auslesen.</translation>
    </message>
    <message>
        <source>No value: the decoder did not answer the read (is it on the programming track?).</source>
        <translation>Kein Wert: Der Decoder hat auf das Lesen nicht geantwortet (steht er auf dem Programmiergleis?).</translation>
    </message>
    <message>
        <source>Refused: the station could not write the CV.</source>
        <translation>Abgelehnt: Die Zentrale konnte die CV nicht schreiben.</translation>
    </message>
    <message>
        <source>Refused by the station.</source>
        <translation>Von der Zentrale abgelehnt.</translation>
    </message>
    <message>
        <source>No answer from the station.</source>
        <translation>Keine Antwort von der Zentrale.</translation>
    </message>
    <message>
        <source>Not sent: the station is not connected.</source>
        <translation>Nicht gesendet: Die Zentrale ist nicht verbunden.</translation>
    </message>
    <message>
        <source>Wait: the station is still busy with the last programming command.</source>
        <translation>Bitte warten: Die Zentrale ist noch mit dem letzten Programmierbefehl beschäftigt.</translation>
    </message>
    <message>
        <source>Only MM2, DCC, mfx and SX1 decoders can be programmed.</source>
        <translation>Nur MM2-, DCC-, mfx- und SX1-Decoder lassen sich programmieren.</translation>
    </message>
    <message>
        <source>MM2 decoders cannot be read: the station can only write their CVs.</source>
        <translation>MM2-Decoder lassen sich nicht lesen: Die Zentrale kann ihre CVs nur schreiben.</translation>
    </message>
    <message>
        <source>The CV must be between %1 and %2 for this protocol.</source>
        <translation>Die CV muss für dieses Protokoll zwischen %1 und %2 liegen.</translation>
    </message>
    <message>
        <source>The mfx index must be between %1 and %2.</source>
        <translation>Der mfx-Index muss zwischen %1 und %2 liegen.</translation>
    </message>
    <message>
        <source>Only mfx CVs have an index.</source>
        <translation>Nur mfx-CVs haben einen Index.</translation>
    </message>
    <message>
        <source>SX1 decoders are programmed on the programming track only.</source>
        <translation>SX1-Decoder werden nur auf dem Programmiergleis programmiert.</translation>
    </message>
    <message>
        <source>Programming modes are for DCC decoders only.</source>
        <translation>Programmierarten gibt es nur für DCC-Decoder.</translation>
    </message>
    <message>
        <source>This DCC programming mode is reserved.</source>
        <translation>Diese DCC-Programmierart ist reserviert.</translation>
    </message>
    <message>
        <source>Bit programming needs a bit position and value.</source>
        <translation>Bitweises Programmieren braucht eine Bitposition und einen Wert.</translation>
    </message>
    <message>
        <source>Choose a SID from 1.</source>
        <translation>Bitte eine SID ab 1 wählen.</translation>
    </message>
    <message>
        <source>No station connected.</source>
        <translation>Keine Zentrale verbunden.</translation>
    </message>
    <message>
        <source>New mfx decoders</source>
        <translation>Neue mfx-Decoder</translation>
    </message>
    <message>
        <source>CV programming</source>
        <translation>CV-Programmierung</translation>
    </message>
    <message>
        <source>Search</source>
        <translation>Lok suchen</translation>
    </message>
    <message>
        <source>The station searches the track for one mfx decoder that is not registered yet</source>
        <translation>Die Zentrale sucht auf dem Gleis einen mfx-Decoder, der noch nicht angemeldet ist</translation>
    </message>
    <message>
        <source>SID:</source>
        <translation>SID:</translation>
    </message>
    <message>
        <source>Register</source>
        <translation>Anmelden</translation>
    </message>
    <message>
        <source>Binds the selected decoder to the SID, then checks that it answers</source>
        <translation>Meldet den gewählten Decoder unter der SID an und prüft dann, ob er antwortet</translation>
    </message>
    <message>
        <source>Locomotive:</source>
        <translation>Lok:</translation>
    </message>
    <message>
        <source>Decoder:</source>
        <translation>Decoder:</translation>
    </message>
    <message>
        <source>CV:</source>
        <translation>CV:</translation>
    </message>
    <message>
        <source>Index:</source>
        <translation>Index:</translation>
    </message>
    <message>
        <source>Value:</source>
        <translation>Wert:</translation>
    </message>
    <message>
        <source>Track:</source>
        <translation>Gleis:</translation>
    </message>
    <message>
        <source>DCC mode:</source>
        <translation>DCC-Modus:</translation>
    </message>
    <message>
        <source>Bit:</source>
        <translation>Bit:</translation>
    </message>
    <message>
        <source>mfx SID</source>
        <translation>mfx-SID</translation>
    </message>
    <message>
        <source>DCC</source>
        <translation>DCC</translation>
    </message>
    <message>
        <source>MM2</source>
        <translation>MM2</translation>
    </message>
    <message>
        <source>SX1</source>
        <translation>SX1</translation>
    </message>
    <message>
        <source>programming track</source>
        <translation>Programmiergleis</translation>
    </message>
    <message>
        <source>main track (write only)</source>
        <translation>Hauptgleis (nur schreiben)</translation>
    </message>
    <message>
        <source>direct</source>
        <translation>direkt</translation>
    </message>
    <message>
        <source>register</source>
        <translation>Register</translation>
    </message>
    <message>
        <source>bit</source>
        <translation>Bit</translation>
    </message>
    <message>
        <source>set</source>
        <translation>gesetzt</translation>
    </message>
    <message>
        <source>Read</source>
        <translation>CV lesen</translation>
    </message>
    <message>
        <source>Write</source>
        <translation>CV schreiben</translation>
    </message>
    <message>
        <source>Registered mfx decoder %1 on SID %2. It is a locomotive of the list now: name it and save it there; search again for more.</source>
        <translation>mfx-Decoder %1 auf SID %2 angemeldet. Er steht jetzt in der Lokliste: dort benennen und speichern; für weitere erneut suchen.</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::RoModuleDialog</name>
    <message>
        <source>Change flags at</source>
        <translation>Änderungsbits bei</translation>
    </message>
    <message>
        <source>Add RO module</source>
        <translation>RO-Modul hinzufügen</translation>
    </message>
    <message>
        <source>Edit RO module</source>
        <translation>RO-Modul ändern</translation>
    </message>
    <message>
        <source>0 (the station&apos;s bus)</source>
        <translation>0 (der Bus der Zentrale)</translation>
    </message>
    <message>
        <source>29-bit (extended)</source>
        <translation>29 Bit (erweitert)</translation>
    </message>
    <message>
        <source>11-bit (standard, CAN adapters only)</source>
        <translation>11 Bit (Standard, nur CAN-Adapter)</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Bus</source>
        <translation>Bus</translation>
    </message>
    <message>
        <source>Frames</source>
        <translation>Rahmen</translation>
    </message>
    <message>
        <source>Request id</source>
        <translation>Anfrage-ID</translation>
    </message>
    <message>
        <source>Answer id</source>
        <translation>Antwort-ID</translation>
    </message>
    <message>
        <source>Relays at</source>
        <translation>Relais bei</translation>
    </message>
    <message>
        <source>Inputs at</source>
        <translation>Eingänge bei</translation>
    </message>
    <message>
        <source>Read inputs every</source>
        <translation>Eingänge lesen alle</translation>
    </message>
    <message>
        <source>RO modules name no ids and no register map; take them from the module&apos;s manual or its switches. The user guide (Help) lists Stellwerk&apos;s defaults.</source>
        <translation>RO-Module nennen weder IDs noch Registerbelegung; entnehmen Sie sie der Anleitung des Moduls oder seinen Schaltern. Das Handbuch (Hilfe) nennt Stellwerks Vorgaben.</translation>
    </message>
    <message>
        <source>count</source>
        <translation>Anzahl</translation>
    </message>
    <message>
        <source>The module needs a name.</source>
        <translation>Das Modul braucht einen Namen.</translation>
    </message>
    <message>
        <source>Another module is called &quot;%1&quot;.</source>
        <translation>Ein anderes Modul heißt bereits „%1“.</translation>
    </message>
    <message>
        <source>Every id and address is a hexadecimal number.</source>
        <translation>Jede ID und Adresse ist eine Hexadezimalzahl.</translation>
    </message>
    <message>
        <source>Register addresses go up to 0xFFFF.</source>
        <translation>Registeradressen gehen bis 0xFFFF.</translation>
    </message>
    <message>
        <source>The module cannot be used so: %1</source>
        <translation>So kann das Modul nicht benutzt werden: %1</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::RoModuleView</name>
    <message>
        <source>Relay %1 was not switched: the module does not answer.</source>
        <translation>Relais %1 wurde nicht geschaltet: das Modul antwortet nicht.</translation>
    </message>
    <message>
        <source>The relays were not switched off: the module does not answer.</source>
        <translation>Die Relais wurden nicht ausgeschaltet: das Modul antwortet nicht.</translation>
    </message>
    <message>
        <source>Not switched: %1</source>
        <translation>Nicht geschaltet: %1</translation>
    </message>
    <message>
        <source>Answers %1 · repeated %2 · timed out %3 · refused %4 · late or foreign %5 · unreadable %6</source>
        <translation>Antworten %1 · wiederholt %2 · ohne Antwort %3 · abgelehnt %4 · verspätet oder fremd %5 · unlesbar %6</translation>
    </message>
    <message>
        <source>Reading the relays…</source>
        <translation>Liest die Relais…</translation>
    </message>
    <message>
        <source>Online. A relay changes colour once the module confirmed it.</source>
        <translation>Online. Ein Relais wechselt die Farbe, sobald das Modul es bestätigt hat.</translation>
    </message>
    <message>
        <source>Offline: the module does not answer. Relays and inputs are %1 until it answers again.</source>
        <translation>Offline: das Modul antwortet nicht. Relais und Eingänge sind %1, bis es wieder antwortet.</translation>
    </message>
    <message>
        <source>Relays (click one to switch it)</source>
        <translation>Relais (zum Schalten anklicken)</translation>
    </message>
    <message>
        <source>All relays off</source>
        <translation>Alle Relais aus</translation>
    </message>
    <message>
        <source>Inputs</source>
        <translation>Eingänge</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::ScheduleDialog</name>
    <message>
        <source>Schedule changed</source>
        <translation>Fahrplan geändert</translation>
    </message>
    <message>
        <source>Keep the changes to the schedule?</source>
        <translation>Die Änderungen am Fahrplan behalten?</translation>
    </message>
    <message>
        <source>Schedule of %1</source>
        <translation>Fahrplan von %1</translation>
    </message>
    <message>
        <source>Stop (block)</source>
        <translation>Halt (Block)</translation>
    </message>
    <message>
        <source>Dwell</source>
        <translation>Haltezeit</translation>
    </message>
    <message>
        <source>&amp;Add stop</source>
        <translation>Halt &amp;hinzufügen</translation>
    </message>
    <message>
        <source>&amp;Remove stop</source>
        <translation>Halt &amp;entfernen</translation>
    </message>
    <message>
        <source>Move &amp;up</source>
        <translation>Nach &amp;oben</translation>
    </message>
    <message>
        <source>Move &amp;down</source>
        <translation>Nach &amp;unten</translation>
    </message>
    <message>
        <source>Run in a &amp;loop (after the last stop, the first again)</source>
        <translation>Im &amp;Kreis fahren (nach dem letzten Halt wieder der erste)</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::SignalGrid</name>
    <message>
        <source>on</source>
        <translation>ein</translation>
    </message>
    <message>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <source>%1: %2, waiting for the device to confirm the change</source>
        <translation>%1: %2, wartet auf die Bestätigung des Geräts</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::SpeedScale</name>
    <message>
        <source>%1 km/h</source>
        <translation>%1 km/h</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::StartupProgress</name>
    <message>
        <source>Step %1 of %2</source>
        <translation>Schritt %1 von %2</translation>
    </message>
    <message>
        <source>file %1 of %2</source>
        <translation>Datei %1 von %2</translation>
    </message>
    <message>
        <source>%1: %2 (%3)</source>
        <translation>%1: %2 (%3)</translation>
    </message>
    <message>
        <source>%1: %2 of %3 (%4)</source>
        <translation>%1: %2 von %3 (%4)</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::StatusPanel</name>
    <message>
        <source>Track current (main)</source>
        <translation>Gleisstrom Hauptgleis</translation>
    </message>
    <message>
        <source>Track current (programming)</source>
        <translation>Gleisstrom Programmiergleis</translation>
    </message>
    <message>
        <source>Track current</source>
        <translation>Gleisstrom</translation>
    </message>
    <message>
        <source>Voltage</source>
        <translation>Spannung</translation>
    </message>
    <message>
        <source>Temperature</source>
        <translation>Temperatur</translation>
    </message>
    <message>
        <source>%1, article %2, version %3</source>
        <translation>%1, Artikel %2, Version %3</translation>
    </message>
    <message>
        <source>No device has described its readings yet.</source>
        <translation>Noch kein Gerät hat seine Messwerte beschrieben.</translation>
    </message>
    <message>
        <source>a device</source>
        <translation>einem Gerät</translation>
    </message>
    <message>
        <source>channel %1</source>
        <translation>Kanal %1</translation>
    </message>
    <message>
        <source>Overload on %1 (%2): the track power is off. Look for a short circuit or a derailed train, then switch the power on again.</source>
        <translation>Überlast an %1 (%2): Der Gleisstrom ist aus. Suchen Sie nach einem Kurzschluss oder einem entgleisten Zug und schalten Sie den Strom dann wieder ein.</translation>
    </message>
    <message>
        <source>Settings</source>
        <translation>Einstellungen</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::StopGoButton</name>
    <message>
        <source>STOP</source>
        <translation>STOPP</translation>
    </message>
    <message>
        <source>Track power is on. Press to switch it off: every train stops (Space)</source>
        <translation>Die Gleisspannung ist an. Drücken schaltet sie aus: Alle Züge halten (Leertaste)</translation>
    </message>
    <message>
        <source>TRACK POWER OFF · press to switch on</source>
        <translation>GLEISSPANNUNG AUS · zum Einschalten drücken</translation>
    </message>
    <message>
        <source>The layout is stopped: the station switched the track power off. Press to switch it on again (GO); trains resume their speeds.</source>
        <translation>Die Anlage ist gestoppt: Die Zentrale hat die Gleisspannung abgeschaltet. Drücken schaltet sie wieder ein (GO); die Züge fahren mit ihren Geschwindigkeiten weiter.</translation>
    </message>
    <message>
        <source>TRAINS HALTED · press to go on</source>
        <translation>ZÜGE ANGEHALTEN · zum Weiterfahren drücken</translation>
    </message>
    <message>
        <source>Every train was halted; the track still has power. Press to let them go on (GO).</source>
        <translation>Alle Züge wurden angehalten; das Gleis hat noch Spannung. Drücken lässt sie weiterfahren (GO).</translation>
    </message>
    <message>
        <source>STOP · power not reported</source>
        <translation>STOPP · Spannung nicht gemeldet</translation>
    </message>
    <message>
        <source>The station has not reported the track power (silent, reconnecting or not yet said). Press to switch it off anyway (Space).</source>
        <translation>Die Zentrale hat die Gleisspannung nicht gemeldet (antwortet nicht, wird neu verbunden oder hat es noch nicht gesagt). Drücken schaltet sie trotzdem aus (Leertaste).</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::StopKeyMenu</name>
    <message>
        <source>Extra STOP &amp;key</source>
        <translation>Zusätzliche STOPP-&amp;Taste</translation>
    </message>
    <message>
        <source>None (Space only)</source>
        <translation>Keine (nur Leertaste)</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::ThrottlePanel</name>
    <message>
        <source>Add throttle</source>
        <translation>Fahrpult hinzufügen</translation>
    </message>
    <message>
        <source>Open one more throttle (up to %1)</source>
        <translation>Ein weiteres Fahrpult öffnen (bis zu %1)</translation>
    </message>
    <message>
        <source>Alt+1…9: keyboard on a throttle · Up/Down or +/−: speed · R: direction · 0–9: F0–F9 · E: stop this loco · Space stays STOP for the layout</source>
        <translation>Alt+1…9: Tastatur auf ein Fahrpult · Pfeil auf/ab oder +/−: Geschwindigkeit · R: Richtung · 0–9: F0–F9 · E: diese Lok anhalten · Leertaste bleibt STOPP für die Anlage</translation>
    </message>
    <message>
        <source>No station connected: throttles drive once a station is ready.</source>
        <translation>Keine Zentrale verbunden: Die Fahrpulte fahren, sobald eine Zentrale bereit ist.</translation>
    </message>
    <message>
        <source>Alt+1…9: drive with the keyboard</source>
        <translation>Alt+1…9: mit der Tastatur fahren</translation>
    </message>
    <message>
        <source>Drive %1 (running)</source>
        <translation>%1 fahren (fährt)</translation>
    </message>
    <message>
        <source>Drive %1</source>
        <translation>%1 fahren</translation>
    </message>
    <message>
        <source>No throttle open. Open one for a locomotive below, or with “Add throttle”.</source>
        <translation>Kein Fahrpult offen. Unten eines für eine Lok öffnen oder mit „Fahrpult hinzufügen“.</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::ThrottleTableModel</name>
    <message>
        <source>OpenRailCAN throttle</source>
        <translation>OpenRailCAN-Handregler</translation>
    </message>
    <message>
        <source>Z21 app or WLANmaus</source>
        <translation>Z21-App oder WLANmaus</translation>
    </message>
    <message>
        <source>WiThrottle or Engine Driver</source>
        <translation>WiThrottle oder Engine Driver</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Adresse</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Drives</source>
        <translation>Fährt</translation>
    </message>
    <message>
        <source>Last message</source>
        <translation>Letzte Nachricht</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::ThrottleWidget</name>
    <message>
        <source>Choose a locomotive…</source>
        <translation>Lok wählen …</translation>
    </message>
    <message>
        <source>Locomotive 0x%1 (not on this station)</source>
        <translation>Lok 0x%1 (nicht auf dieser Zentrale)</translation>
    </message>
    <message>
        <source>Locomotive 0x%1 (waiting for the station)</source>
        <translation>Lok 0x%1 (wartet auf die Zentrale)</translation>
    </message>
    <message>
        <source>Alt+%1 puts the keyboard on this throttle</source>
        <translation>Alt+%1 legt die Tastatur auf dieses Fahrpult</translation>
    </message>
    <message>
        <source>Close this throttle</source>
        <translation>Dieses Fahrpult schließen</translation>
    </message>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>%1 km/h</source>
        <translation>%1 km/h</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>◀ Backward</source>
        <translation>◀ Rückwärts</translation>
    </message>
    <message>
        <source>Forward ▶</source>
        <translation>Vorwärts ▶</translation>
    </message>
    <message>
        <source>Change direction (R); the station stops the locomotive first</source>
        <translation>Fahrtrichtung wechseln (R); die Zentrale hält die Lok vorher an</translation>
    </message>
    <message>
        <source>Stop loco</source>
        <translation>Lok anhalten</translation>
    </message>
    <message>
        <source>Speed: %1 % (Up/Down, +/-, PageUp/PageDown)</source>
        <translation>Geschwindigkeit: %1 % (Pfeil auf/ab, +/-, Bild auf/ab)</translation>
    </message>
    <message>
        <source>The station did not acknowledge the last command: %1</source>
        <translation>Die Zentrale hat den letzten Befehl nicht bestätigt: %1</translation>
    </message>
    <message>
        <source>no locomotive</source>
        <translation>keine Lok</translation>
    </message>
    <message>
        <source>Change locomotive</source>
        <translation>Lok wechseln</translation>
    </message>
    <message>
        <source>%1 is running (%2). Drive %3 with this throttle instead?</source>
        <translation>%1 fährt (%2). Stattdessen %3 mit diesem Fahrpult fahren?</translation>
    </message>
    <message>
        <source>%1 keeps running at its speed; this throttle no longer drives it.</source>
        <translation>%1 fährt mit ihrer Geschwindigkeit weiter; dieses Fahrpult steuert sie dann nicht mehr.</translation>
    </message>
    <message>
        <source>Drive %1</source>
        <translation>%1 fahren</translation>
    </message>
    <message>
        <source>Keep %1</source>
        <translation>Bei %1 bleiben</translation>
    </message>
    <message>
        <source>Emergency stop for this locomotive only (E); STOP in the toolbar stops the whole layout</source>
        <translation>Nothalt nur für diese Lok (E); STOP in der Werkzeugleiste hält die ganze Anlage an</translation>
    </message>
    <message>
        <source>The speed the station confirmed</source>
        <translation>Die Geschwindigkeit, die die Zentrale bestätigt hat</translation>
    </message>
    <message>
        <source>Requested: %1</source>
        <translation>Angefordert: %1</translation>
    </message>
    <message>
        <source>Sent to the station; the number above changes when it confirms</source>
        <translation>An die Zentrale gesendet; die Zahl darüber ändert sich, sobald sie bestätigt</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::TrackPlanPanel</name>
    <message>
        <source>Cannot open the layout: %1</source>
        <translation>Das Gleisbild kann nicht geöffnet werden: %1</translation>
    </message>
    <message>
        <source>There is no track plan to export: connect to a station or open a layout first.</source>
        <translation>Es gibt kein Gleisbild zum Exportieren: zuerst mit einer Zentrale verbinden oder ein Gleisbild öffnen.</translation>
    </message>
    <message>
        <source>Cannot export the layout: %1</source>
        <translation>Das Gleisbild kann nicht exportiert werden: %1</translation>
    </message>
    <message>
        <source>Page %1</source>
        <translation>Seite %1</translation>
    </message>
    <message>
        <source>Open layout...</source>
        <translation>Gleisbild öffnen …</translation>
    </message>
    <message>
        <source>Show the track plan of a CS2 configuration folder</source>
        <translation>Das Gleisbild eines CS2-Konfigurationsordners zeigen</translation>
    </message>
    <message>
        <source>Station&apos;s plan</source>
        <translation>Gleisbild der Zentrale</translation>
    </message>
    <message>
        <source>Write the layout as a CS2 configuration folder</source>
        <translation>Das Gleisbild als CS2-Konfigurationsordner schreiben</translation>
    </message>
    <message>
        <source>Zoom in</source>
        <translation>Vergrößern</translation>
    </message>
    <message>
        <source>Zoom out</source>
        <translation>Verkleinern</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Einpassen</translation>
    </message>
    <message>
        <source>No track plan: connect to a station or open a CS2 layout folder.</source>
        <translation>Kein Gleisbild: mit einer Zentrale verbinden oder einen CS2-Gleisbildordner öffnen.</translation>
    </message>
    <message>
        <source>Files: %1</source>
        <translation>Dateien: %1</translation>
    </message>
    <message>
        <source>Live from the station</source>
        <translation>Live von der Zentrale</translation>
    </message>
    <message numerus="yes">
        <source>The layout&apos;s files disagree in %n place(s):</source>
        <translation>
            <numerusform>Die Dateien des Gleisplans widersprechen sich an %n Stelle:</numerusform>
            <numerusform>Die Dateien des Gleisplans widersprechen sich an %n Stellen:</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>... and %n more.</source>
        <translation>
            <numerusform>... und %n weitere.</numerusform>
            <numerusform>... und %n weitere.</numerusform>
        </translation>
    </message>
    <message>
        <source>Export layout...</source>
        <translation>Gleisbild exportieren …</translation>
    </message>
    <message>
        <source>Locomotive on it: %1</source>
        <translation>Lok darauf: %1</translation>
    </message>
    <message numerus="yes">
        <source>%1 is missing: the %n page file(s) found in gleisbilder/ are shown in the order of their names. Export the layout to write a new gleisbild.cs2 for them.</source>
        <translation>
            <numerusform>%1 fehlt: die %n Seitendatei aus gleisbilder/ wird gezeigt. Exportieren Sie das Gleisbild, um eine neue gleisbild.cs2 für sie zu schreiben.</numerusform>
            <numerusform>%1 fehlt: die %n Seitendateien aus gleisbilder/ werden in der Reihenfolge ihrer Namen gezeigt. Exportieren Sie das Gleisbild, um eine neue gleisbild.cs2 für sie zu schreiben.</numerusform>
        </translation>
    </message>
    <message>
        <source>This page has nothing to show: its name cannot be a file name, so no file was looked for.</source>
        <translation>Diese Seite zeigt nichts: ihr Name kann kein Dateiname sein, darum wurde keine Datei gesucht.</translation>
    </message>
    <message>
        <source>This page has nothing to show: its file %1 is missing.</source>
        <translation>Diese Seite zeigt nichts: ihre Datei %1 fehlt.</translation>
    </message>
    <message>
        <source>This page has nothing to show: its file %1 could not be read.</source>
        <translation>Diese Seite zeigt nichts: ihre Datei %1 ließ sich nicht lesen.</translation>
    </message>
    <message>
        <source>Block %1 &apos;%2&apos;</source>
        <translation>Block %1 „%2“</translation>
    </message>
    <message>
        <source>Problem: %1</source>
        <translation>Problem: %1</translation>
    </message>
    <message>
        <source>Block %1 &apos;%2&apos;...</source>
        <translation>Block %1 „%2“ …</translation>
    </message>
    <message>
        <source>Blocks</source>
        <translation>Blöcke</translation>
    </message>
    <message>
        <source>Outline each block with its name, and list and mark the problems of the drawing; then a click on a block&apos;s track says where it leads</source>
        <translation>Jeden Block mit seinem Namen umranden und die Probleme der Zeichnung auflisten und markieren; ein Klick auf das Gleis eines Blocks sagt dann, wohin es führt</translation>
    </message>
    <message>
        <source>Station memory %1: %2</source>
        <translation>Speicher der Zentrale %1: %2</translation>
    </message>
    <message>
        <source>Station memory %1</source>
        <translation>Speicher der Zentrale %1</translation>
    </message>
    <message>
        <source>Announced on the station&apos;s bus: %1</source>
        <translation>Auf dem Bus der Zentrale gemeldet: %1</translation>
    </message>
    <message>
        <source>Place a train in %1...</source>
        <translation>Zug in %1 aufgleisen ...</translation>
    </message>
    <message>
        <source>Remove %1 from %2</source>
        <translation>%1 aus %2 herausnehmen</translation>
    </message>
    <message>
        <source>Drop the locomotive on a block&apos;s track to place it there.</source>
        <translation>Lassen Sie die Lok auf dem Gleis eines Blocks los, um sie dort aufzugleisen.</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::TrafficStatus</name>
    <message>
        <source>Frames in %1 · out %2</source>
        <translation>Telegramme ein %1 · aus %2</translation>
    </message>
    <message>
        <source>Frames received from and sent to the station since connecting; %1 malformed, %2 dropped, %3 reconnects</source>
        <translation>Seit dem Verbinden von der Zentrale empfangene und an sie gesendete Telegramme; %1 fehlerhaft, %2 verworfen, %3 Neuverbindungen</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::TurnoutKey</name>
    <message>
        <source>part of %1</source>
        <translation>Teil von %1</translation>
    </message>
    <message>
        <source>Switch %1 to %2</source>
        <translation>%1 auf %2 stellen</translation>
    </message>
    <message>
        <source>%1 (%2), address %3: %4</source>
        <translation>%1 (%2), Adresse %3: %4</translation>
    </message>
    <message>
        <source>Address %1 has no article; it switches as an MM2 address</source>
        <translation>Adresse %1 ist kein Magnetartikel zugeordnet; sie schaltet als MM2-Adresse</translation>
    </message>
    <message>
        <source>Address %1 belongs to %2, which starts on %3</source>
        <translation>Adresse %1 gehört zu %2 (beginnt bei Adresse %3)</translation>
    </message>
    <message>
        <source>Switching: waiting for the station to confirm</source>
        <translation>Schaltet: wartet auf die Bestätigung der Zentrale</translation>
    </message>
    <message>
        <source>The station did not confirm the last switching</source>
        <translation>Die Zentrale hat den letzten Schaltbefehl nicht bestätigt</translation>
    </message>
    <message>
        <source>no article</source>
        <translation>kein Magnetartikel</translation>
    </message>
    <message>
        <source>not known</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Stellung</translation>
    </message>
    <message>
        <source>Switch %1 to another position</source>
        <translation>%1 in eine andere Stellung schalten</translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::TurnoutPanel</name>
    <message>
        <source>Articles on the keyboard: %1</source>
        <translation>Magnetartikel im Keyboard: %1</translation>
    </message>
    <message>
        <source>Article %1</source>
        <translation>Magnetartikel %1</translation>
    </message>
    <message>
        <source>Page %1: %2–%3</source>
        <translation>Seite %1: %2–%3</translation>
    </message>
    <message>
        <source>The keyboard appears when a station is connected.</source>
        <translation>Das Keyboard erscheint, sobald eine Zentrale verbunden ist.</translation>
    </message>
    <message>
        <source>Previous page (Page Up)</source>
        <translation>Vorige Seite (Bild auf)</translation>
    </message>
    <message>
        <source>Next page (Page Down)</source>
        <translation>Nächste Seite (Bild ab)</translation>
    </message>
    <message>
        <source>Keyboard page: 16 addresses each, as on the Central Station</source>
        <translation>Keyboard-Seite: je 16 Adressen, wie auf der Central Station</translation>
    </message>
    <message>
        <source>Articles on the keyboard: %1 · positions %2</source>
        <translation>Magnetartikel im Keyboard: %1 · Stellungen %2</translation>
    </message>
</context>
</TS>
