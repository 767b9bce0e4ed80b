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
    <name>AccessoryIcon</name>
    <message>
        <source>unknown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Straight</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Diverging</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Right</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Straight, diverging</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Diverging, straight</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hp0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hp1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sh1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hp2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sh0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Uncouple</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rest</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Track %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Green</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Red</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>AnnouncedStateText</name>
    <message>
        <source>not active</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>active</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>free</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>occupied</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>waiting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reserved</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>BlockDescription</name>
    <message>
        <source>Block %1 &apos;%2&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n tile(s), %1 mm</source>
        <translation>
            <numerusform>%n tile, %1 mm</numerusform>
            <numerusform>%n tiles, %1 mm</numerusform>
        </translation>
    </message>
    <message>
        <source>Contact %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Contact %1 &apos;%2&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of feedback device %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Signal &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Signal %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A signal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1, for trains towards end %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>From end %1 (%2):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>to block %1 &apos;%2&apos;, end %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>directly</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>over %n tile(s) of track without a contact</source>
        <translation>
            <numerusform>over %n tile of track without a contact</numerusform>
            <numerusform>over %n tiles of track without a contact</numerusform>
        </translation>
    </message>
    <message>
        <source>the turnout at %1 %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>turnout %1 %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>turnout %1 &apos;%2&apos; %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>over %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>across the crossing(s) at %1</source>
        <translation>
            <numerusform>across the crossing at %1</numerusform>
            <numerusform>across the crossings at %1</numerusform>
        </translation>
    </message>
    <message>
        <source>&apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>set by route(s) %1</source>
        <translation>
            <numerusform>set by route %1</numerusform>
            <numerusform>set by routes %1</numerusform>
        </translation>
    </message>
    <message>
        <source>The track ends at a buffer stop.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The track ends at a turntable.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The track ends without a buffer stop.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No way leads from here to another block.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>page %1, column %2, row %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>straight</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>diverging</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>right</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>straight and diverging</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>diverging and straight</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>across</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Contacts:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Signals:</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>CorrectionText</name>
    <message>
        <source>%1: the station carried out a command late that had failed (%2); it stays, as it brings nothing into motion.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>set back to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the station carried out a command late that had failed (%2); %3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: a command that had failed (%2) could still reach the station; %3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Accessory %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Address %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Track power</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>speed %1 %</source>
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
    <message>
        <source>F%1 on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>F%1 off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>position %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>off</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FunctionIcons</name>
    <message>
        <source>Function</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Light</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Interior light</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cab light</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sound</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Horn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Whistle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bell</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Smoke</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Coupler</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shunting speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Brake sound</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pantograph</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Acceleration delay off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Announcement</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>GraphProblemText</name>
    <message>
        <source>Page %1, column %2, row %3: %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The track ends here without a buffer stop, or does not meet the track of the tile beside it; add the missing track or a buffer stop, or turn a tile.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This tile (%1) joins no other track; move it onto the track or remove it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has a side without track, so the way through it there leads nowhere; add the track or a buffer stop.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The track from here to the next turnout or end has no contact, so a train there cannot be seen; add a contact where trains may stop.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The arrow names page %1, which the track plan does not have; the track ends here.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The arrow leads to page %1, whose file is missing; the track ends here.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The arrow to page %1 has no arrow back on that page, so the track ends here; add one where the track goes on.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is drawn twice on this page, on two stretches of track; one contact can watch only one block, so both are taken as block &apos;%2&apos;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is drawn on another page as well, and the drawings join different track; make the pages agree.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A route sets %1 so that it leads from no block to another as the plan draws it; check the route&apos;s turnouts against the plan.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Route %1 sets turnouts that together lead from no block to another as the plan draws them; check the route&apos;s turnouts against the plan.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A way over this tile needs %1 in two positions at once (it is drawn more than once, or passed twice), so that way is left out; give the drawings their own articles if they are separate turnouts.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>From this tile the track branches into more ways than are followed; add contacts between the turnouts so that it splits into blocks.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>The drawing of the track plan has %n problem(s):</source>
        <translation>
            <numerusform>The drawing of the track plan has %n problem:</numerusform>
            <numerusform>The drawing of the track plan has %n problems:</numerusform>
        </translation>
    </message>
    <message>
        <source>&apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The turnout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Turnout %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Turnout %1 &apos;%2&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Contact %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Contact %1 &apos;%2&apos;</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>NotReported</name>
    <message>
        <source>not reported</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not reported: the station is silent or being reconnected. This is the last state it reported; it may no longer be true.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>StopReasonText</name>
    <message>
        <source>%1 is no longer seen where it stood: place it again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 entered &quot;%2&quot; on the way of %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 ran on into &quot;%2&quot;, which was not reserved for it: track power off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 stopped: an unknown occupant in &quot;%2&quot; on its way</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 did not arrive in &quot;%2&quot; in time: stopped, place it again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>turnout %1 was not confirmed in position %2 after %3 attempts: %4 does not depart, its way is given back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>turnout %1 was switched to position %2 on the way reserved for %3: stopped</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>TileMenu</name>
    <message>
        <source>Locomotive on this contact</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not known</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run from Stellwerk</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run from the station&apos;s memory (%1)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>TrackTileInfo</name>
    <message>
        <source>Straight track</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Double curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Crossing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Underpass</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Buffer stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tunnel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left turnout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Right turnout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Y turnout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Three-way turnout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Double slip</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Double slip (two drives)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scissors crossover</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>S88 contact</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>S88 contact (curve)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>S88 contact (double curve)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Link to a page</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Route button</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Level crossing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Slip turnout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Semaphore signal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Signal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Uncoupler</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lamp</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Turntable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Transfer table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unknown element (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop (Hp0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Proceed (Hp1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Slow (Hp2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shunting (Sh1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop (Sh0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Straight</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Right</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Diverging</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Accessory %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Contact %1 (device %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Route %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>TrainStateText</name>
    <message>
        <source>automatic, waiting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>automatic, setting its way</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>automatic, running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>automatic, braking</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stopped, waiting for Resume</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stopped, state unknown (the station was silent)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>fault: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>lost: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not placed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not placed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>automatic, waiting for Resume</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>manual (taken by a throttle)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>manual</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none: any free block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1%2 (%3 s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1, done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1, loop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1, once</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::AftermathMenu</name>
    <message numerus="yes">
        <source>The layout is back in step: %n states read again.</source>
        <translation>
            <numerusform>The layout is back in step: %n state read again.</numerusform>
            <numerusform>The layout is back in step: %n states read again.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The layout is back in step, but %n states got no answer.</source>
        <translation>
            <numerusform>The layout is back in step, but %n state got no answer.</numerusform>
            <numerusform>The layout is back in step, but %n states got no answer.</numerusform>
        </translation>
    </message>
    <message>
        <source>Stopping every locomotive and reading every state again…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sending every locomotive its confirmed speed and reading every state again…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>After a &amp;failed command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Bring back what the station last confirmed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Stop every locomotive that had one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bring the layout back in &amp;step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sends every locomotive the speed the station last confirmed (or stops them all, as chosen under After a failed command) and reads every state again</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::AutomaticPanel</name>
    <message>
        <source>Trains&apos; book: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Train</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>State</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Destination</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Schedule</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Place…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Put a locomotive in a block of the track plan, facing one end</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>S&amp;tart</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The automation drives the train from where it stands</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>St&amp;op</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The train stops and becomes manual; its track stays reserved for it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Hand back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Give a train a throttle took back to the automation, where it stands</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sche&amp;dule…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The blocks the train runs to, how long it stands at each, once or in a loop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Re&amp;move</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Take the train off the automation and out of the book</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Resume</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>After STOP, a fault or a restart: the automatic trains go on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop all at next stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Every automatic train runs on to its next stop and stays there, manual</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Automatic operation needs a station (or an opened layout) with a track plan.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Automation is stopped (STOP, a fault or a restart): nothing moves until you press Resume.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No trains yet: place one with Place…, then start it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Trains are saved in %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Last fault: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::BindingsDialog</name>
    <message>
        <source>Device bindings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Article</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switched by</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Contact</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lit by</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Articles switched by a device instead of the station</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Contacts lit by a device instead of an S88 module</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RO relay</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OpenRailCAN decoder output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OpenRailCAN decoder (its position)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RO input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OpenRailCAN encoder input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The module&apos;s name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The decoder&apos;s bus id (Ziel-Id)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>relay </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>output </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The encoder&apos;s UID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>input </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose an article and the module or decoder that switches it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot; is no bus id: write it in hexadecimal, 0x0000 to 0xFFFF.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose a contact and the module or encoder that lights it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot; is no UID: write it in hexadecimal.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>module %1, contact %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>relay %1 of “%2”</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OpenRailCAN decoder %1, output %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OpenRailCAN decoder %1 (its position)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>input %1 of “%2”</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OpenRailCAN encoder %1, input %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::BlockLegend</name>
    <message>
        <source>Blocks:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>free</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reserved</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>train in it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown occupant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>fault</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A train&apos;s blocks are solid and named with it; the blocks and turnouts reserved for its way hatched; a block occupied by something no train can have reached cross-hatched; a train stopped by a fault dotted. Free blocks are outlined while &quot;Blocks&quot; is on.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::BusMonitorFilterBar</name>
    <message>
        <source>the Loc-ID is not understood; write e.g. 0xC003, 49155 or dcc 3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the handheld is not understood; write its node, e.g. 43, or its name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Find text, e.g. speed=0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All protocols</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CS2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>M-CAN</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OpenRailCAN</source>
        <translation></translation>
    </message>
    <message>
        <source>RO</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Foreign</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show only frames of one protocol; foreign frames belong to none that is expected on their bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Handheld</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show only the M-CAN frames of one MS1 handheld: its node (43, or its master&apos;s 42) or the name it sent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All commands</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show only frames of one command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Loc-ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show only frames for one Loc-ID: 0xC003, 49155 or a protocol and address such as dcc 3, mfx 5, mm2 80</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::BusMonitorModel</name>
    <message>
        <source>Time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Direction</source>
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
        <source>Frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>← received</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>→ sent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bus</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::BusMonitorPanel</name>
    <message>
        <source>Recording stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The frames could not be written to %1; recording stopped.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Record frames to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>candump logs (*.log);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recording not started</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 cannot be written: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open a candump log</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Log file</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%Ln row(s) match the filter</source>
        <translation>
            <numerusform>%Ln row matches the filter</numerusform>
            <numerusform>%Ln rows match the filter</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>paused, %Ln frame(s) arrived since</source>
        <translation>
            <numerusform>paused, %Ln frame arrived since</numerusform>
            <numerusform>paused, %Ln frames arrived since</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Resume</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop adding rows; frames that arrive meanwhile are kept and shown on resume</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>C&amp;lear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recording to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write every frame from now on to a candump log file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Open log…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Keep:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How many frames the table keeps; older ones are dropped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>line %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 cannot be read: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%Ln frame(s) seen</source>
        <translation>
            <numerusform>%Ln frame seen</numerusform>
            <numerusform>%Ln frames seen</numerusform>
        </translation>
    </message>
    <message>
        <source>filtering, %1 % done</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%Ln line(s) skipped; %1</source>
        <translation>
            <numerusform>%Ln line skipped; %1</numerusform>
            <numerusform>%Ln lines skipped; %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Stop re&amp;cording</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Re&amp;cord…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Play the frames of a candump log file instead of the live ones</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Replayed %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Replaying %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1× (as recorded)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>2×</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>10×</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>As fast as possible</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How fast the log plays</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Res&amp;ume replay</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pa&amp;use replay</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back to li&amp;ve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop the replay, clear the table and show the station&apos;s frames again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>station</source>
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
    <message>
        <source>&amp;Recent:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose a station used before…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>None yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Simulated station (demo layout, no hardware needed)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CS2 or CS3 over &amp;UDP (the CAN gateway, ports 15731/15730)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CS2 or CS3 over &amp;TCP (port 15731)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Host:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CAN &amp;interface (Gleisbox through a CAN adapter)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Interface:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>plugin/interface, e.g. socketcan/can0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Look again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>List the CAN interfaces Qt&apos;s plugins find now</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Address:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Further &amp;buses:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Optional: more CAN buses to watch beside the station, such as a USB-CAN adapter wired to relay modules; separate several with commas. Their frames show in the bus monitor.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The further bus %1 cannot be used: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The further bus %1 is the station&apos;s own address.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Examples:
udp://192.168.2.5 — a CS2 with its CAN-UDP gateway switched on
tcp://192.168.2.5 — a CS3, or a CS2 over TCP
tcp://127.0.0.1:15731?http=8080 — stellwerk-sim, its pictures on port 8080
can://socketcan/can0 — a Gleisbox through a CAN adapter</source>
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
    <message>
        <source>Try: restart Stellwerk; if it happens again, report the message above.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Try: check that the station is on and reachable at this address, and that its CAN-UDP gateway sends to this computer (CS2: Setup → IP → CAN gateway).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Try: check that the station is on and reachable at this address and port.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Try: check that the CAN interface exists and is up (SocketCAN: ip link set can0 up type can bitrate 250000) and that the Gleisbox has power.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Try: correct the address in Station → Connect…, for example udp://192.168.2.5.</source>
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
    <message>
        <source>%1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Locomotive</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::CorrectionNotice</name>
    <message numerus="yes">
        <source>%n set back after trouble</source>
        <translation>
            <numerusform>%n set back after trouble</numerusform>
            <numerusform>%n set back after trouble</numerusform>
        </translation>
    </message>
    <message>
        <source>Dismiss</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Everything set back since the last Dismiss, with its time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>I have read it: hide this strip until something is set back again</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::DeviceSettingEditor</name>
    <message>
        <source>writing…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>accepted ✓</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>refused ✗</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no answer ✗</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The device refused the value and keeps its setting.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The device did not answer; its setting is unknown. Try again.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::DeviceTableModel</name>
    <message>
        <source>Device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kind</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Address</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>State</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>booster / system device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>throttle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>decoder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>encoder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>legacy decoder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>legacy encoder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>type %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>gone</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OpenRailCAN %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bus id %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>getting its bus id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>online</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>offline: misses its pings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>refused: its bus id is taken</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>RO module, %n relay(s), %1-bit</source>
        <translation>
            <numerusform>RO module, %n relay, %1-bit</numerusform>
            <numerusform>RO module, %n relays, %1-bit</numerusform>
        </translation>
    </message>
    <message>
        <source>bus %1: %2 / %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>refused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bus not connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading its relays</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>offline: does not answer</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::DevicesPanel</name>
    <message>
        <source>Not connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OpenRailCAN: Stellwerk is not the central.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OpenRailCAN: its bus is not connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>OpenRailCAN: %1 of %n device(s) online.</source>
        <translation>
            <numerusform>OpenRailCAN: %1 of %n device online.</numerusform>
            <numerusform>OpenRailCAN: %1 of %n devices online.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>RO modules: %1 of %n online.</source>
        <translation>
            <numerusform>RO modules: %1 of %n online.</numerusform>
            <numerusform>RO modules: %1 of %n online.</numerusform>
        </translation>
    </message>
    <message>
        <source>Refused: %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Modules you add or change are used from the next connection (Station ▸ Connect).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove RO module</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove the module &quot;%1&quot; from the station settings? Its bindings stay until you remove them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add RO module…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bindings…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose a device to see its relays, outputs and inputs.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The demo station brings its own devices; modules you add are for your own station.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The demo&apos;s bindings: what you change here lasts until you connect again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved with the station settings.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::FoundDecoders</name>
    <message>
        <source>mfx UID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>State</source>
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
    <message>
        <source>Paste CAN frames of the CS2 or of MS1 handhelds (M-CAN), one per line, as written in the Märklin documents (00004711 5 00 00 00 00 00), by candump (00004711#0000000000) or as 13-byte network frames in hex. Lines starting with # are ignored; the lines are read in order, as one bus.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::FunctionPad</name>
    <message>
        <source>on while held</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>on for %n s</source>
        <translation>
            <numerusform>on for %n s</numerusform>
            <numerusform>on for %n s</numerusform>
        </translation>
    </message>
    <message>
        <source>on/off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>F%1: %2 (%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The station did not acknowledge the last command: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::GaugeWidget</name>
    <message>
        <source>%1: no answer to the last request, the value is old</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::GuideBrowser</name>
    <message>
        <source>Stellwerk user guide</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Contents</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The user guide is not installed here. It is in the folder docs/guide of Stellwerk&apos;s sources, and after installing in share/doc/stellwerk/guide.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::HandheldDetails</name>
    <message>
        <source>Selected handheld</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name, up to 16 characters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rename</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Send the name to the handheld; it shows it from now on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Down</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The locomotives the handheld offers, in its order; remembered for this handheld</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Loc-ID 0x%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The stack is full (%1 locomotives)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::HandheldTableModel</name>
    <message>
        <source>logging in (stage %1 of 7)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading its locomotives</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>online</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>online at another master</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>silent: %n poll(s) left</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>silent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>offline</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>in its boot loader</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>refused: somebody else drives it</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n locomotive(s)</source>
        <translation type="unfinished">
            <numerusform>%n locomotive</numerusform>
            <numerusform>%n locomotives</numerusform>
        </translation>
    </message>
    <message>
        <source>UID %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node %1; its master&apos;s node is %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Handheld</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>State</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Locomotive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Functions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stack</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::HandheldsPanel</name>
    <message>
        <source>Not connected: no handhelds to show.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stellwerk is the master of the MS1 handhelds on this bus: plug one in to drive with it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stellwerk waits until it knows the devices on the bus before it answers any handheld.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stellwerk only watches the handhelds: the Central Station is their master.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stellwerk only watches the handhelds: another master (node %1) answers them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stellwerk only watches the handhelds, as chosen.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The handheld %1 sits in its boot loader: only a CS1 or an ECoS can flash it back to life. Stellwerk never sends it there and never flashes it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Act as master for MS1 handhelds</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Answer MS1 handhelds on the station&apos;s bus, unless a Central Station or another master does; off: only watch them</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Make it quiet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tell it to stop sending; it stays in its boot loader</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stellwerk only watches the handhelds: another master answers them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Another master answers the handhelds on this bus: Stellwerk only watches them</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MS1 handhelds (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Phones and other throttles (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Phones of the Z21 app and WLANmaus, Engine Driver and WiThrottle, and OpenRailCAN throttles. Select a phone to disconnect it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Let the selected phone go: its locomotives are stopped</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::KeyList</name>
    <message>
        <source>Keys</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What they do</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Space</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Alt+1 … Alt+9</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Put the keyboard on throttle 1 … 9</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Up, Down, +, −</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On a throttle: faster, slower</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On a throttle: much faster, much slower</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>R</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On a throttle: change direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>0 … 9</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On a throttle: functions F0 … F9</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>E</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On a throttle: stop this locomotive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>STOP: track power off for the whole layout, from anywhere (also while a throttle has the keys)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>STOP, the extra STOP key (choose another under Station → Extra STOP key)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Turnout keyboard: previous page, next page</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Turnout keyboard: switch the key that has the focus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Locomotives: save the changes to a folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Locomotives: remove the selected locomotive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bus monitor: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On the bare window (nothing open on top): STOP, track power off for the whole layout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>In a dialog, menu or popup: closes it, and nothing else</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Locomotives: change the selected locomotive&apos;s Z21 address</source>
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
    <name>stellwerk::ui::LayoutFileActions</name>
    <message>
        <source>Layout exported</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The layout was written to %1 as a CS2 configuration folder.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No layouts opened yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clear the list</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open &amp;recent layout</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::LayoutFileDialog</name>
    <message>
        <source>Open a CS2 layout folder or track plan page</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CS2 track plan files (*.cs2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export the layout into a folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The folder %1 cannot be made here. Choose another place.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::LayoutOverview</name>
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
    <name>stellwerk::ui::LayoutStateBanner</name>
    <message>
        <source>Not reported: the station is silent or being reconnected. Greyed states are the last it reported.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Track power not reported yet: the station has not said whether trains may run.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>LAYOUT STOPPED: track power is off. Press the power key in the toolbar to switch it on.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>LAYOUT HALTED: every train was halted. Press the power key in the toolbar to go on.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::LocomotiveFileModel</name>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Address</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Decoder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Icon</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Functions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MM2 (programmable)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MM2 (DIL switches)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MM (programmable)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MM2 (mLD/mSD)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DCC</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mfx</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SX1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DCC %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mfx SID %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SX1 %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MM2 %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The address the Z21 app and WLANmaus use for this locomotive; double-click to change it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A DCC locomotive has its own address on the Z21 too</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Z21 address</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A Z21 address is a number from %1 to %2; &apos;%3&apos; keeps %4.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Z21 address %1 is kept for another locomotive; &apos;%2&apos; keeps %3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos; already has Z21 address %2; &apos;%3&apos; keeps %4.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos; has Z21 address %2 now.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::LocomotiveForm</name>
    <message>
        <source>allowed: %1–%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Decoder:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Address:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Icon</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Trigger</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>latching</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>momentary</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>timed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>as in the file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shows</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::LocomotivePanel</name>
    <message>
        <source>New locomotive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enter the new locomotive and press Add.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Changed. Save to write lokomotive.cs2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Deleted. Save to write lokomotive.cs2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete locomotive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete &apos;%1&apos; from the locomotive list?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The new mfx decoder is in the list as &apos;%1&apos;. Save to write lokomotive.cs2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save lokomotive.cs2 into a CS2 configuration folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not saved: %1. The edits are kept.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved to %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Locomotives</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n locomotive(s), changed and not saved</source>
        <translation>
            <numerusform>%n locomotive, changed and not saved</numerusform>
            <numerusform>%n locomotives, changed and not saved</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n locomotive(s)</source>
        <translation>
            <numerusform>%n locomotive</numerusform>
            <numerusform>%n locomotives</numerusform>
        </translation>
    </message>
    <message>
        <source>Give the locomotive a name.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The name must be on one line.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Another locomotive is already called &apos;%1&apos;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose the decoder type.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The address must be between %1 and %2 for this decoder.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos; already uses this address.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>F%1 is not a function key (F0 to F31).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The icon of F%1 must be between %2 and %3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The time of F%1 must be between %2 and %3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Select a locomotive first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No station connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The station has not sent its locomotive list (lokomotive.cs2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save to folder…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writes config/lokomotive.cs2 into the folder you choose</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Revert</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The station sent its locomotive list again; your unsaved changes are kept.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unsaved locomotive changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The locomotive list has changes that are not saved. Save them before %1?</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::LocomotivePictureBook</name>
    <message>
        <source>No picture: no station</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This locomotive names no picture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The picture “%1” is damaged</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Picture “%1”</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Loading the picture “%1”…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No picture “%1”: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not a usable file name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no station to ask and no icons folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the station has none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the file is not a usable PNG picture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the station did not send it; asked again when it is back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not known yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Looked for at %1</source>
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
    <message>
        <source>%1 (%2)</source>
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
        <source>Status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bus monitor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Stop everything</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch the track power off: every train stops</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop and go</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Panels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Reset panel layout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Put every panel back where it was at the first start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keyboard</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Throttles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Locomotives</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Programming</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Overview</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>quitting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>opening another layout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connecting again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Space</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Space, %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>User &amp;guide</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read how to use Stellwerk</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Keys</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Every key the desk answers to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Devices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set back after trouble</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Phones and Tablets…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Let the Z21 app, a WLANmaus, Engine Driver or WiThrottle drive the layout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Handhelds and phones</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::OrcDeviceView</name>
    <message>
        <source>OpenRailCAN device %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Inputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Outputs as the decoder last confirmed them (%1 until it confirms a switch)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The central no longer knows this device.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1, bus id %2, version %3.%4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Getting its bus id from the central.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Online: answers the central&apos;s pings.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Offline: missed %n ping(s); what it reported is %1.</source>
        <translation>
            <numerusform>Offline: missed %n ping; what it reported is %1.</numerusform>
            <numerusform>Offline: missed %n pings; what it reported is %1.</numerusform>
        </translation>
    </message>
    <message>
        <source>Refused: another device has its bus id and it did not take a new one.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the whole device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>output %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No overload.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OVERLOAD: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::OtherThrottles</name>
    <message>
        <source>CAN bus</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::PhoneStatus</name>
    <message>
        <source>Phones: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No phone or tablet is connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connected:
%1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::PhonesDialog</name>
    <message>
        <source>Phones and Tablets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Phones and tablets drive the layout as throttles: the Z21 app and the WLANmaus through the Z21 server, Engine Driver and WiThrottle through the WiThrottle server.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Z21 server (Z21 app, WLANmaus)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>WiThrottle server (Engine Driver, WiThrottle)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>every phone in the network</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Only these phones (addresses):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>all network interfaces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Listen on address:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Port:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a network address of this computer (for example 192.168.1.20); leave it empty to listen on all of them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The allowed phones must be network addresses, separated by commas (for example 192.168.1.30, 192.168.1.31).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not start: %1. Another program may use the port; choose another one.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::PlaceTrainDialog</name>
    <message>
        <source>End %1, %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Locomotive:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Length:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Place</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The train is tracked from here on: put it on the track in %1 first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>towards %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> or </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>towards a buffer stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>towards a turntable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>towards the end of the track</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Place a train</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>May change direction in any block (push-pull)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Block:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Its front faces:</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::PlanAutomation</name>
    <message>
        <source>for %1</source>
        <comment>a block reserved for a train</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown occupant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 · fault</source>
        <comment>a train stopped by a fault</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Automation: free</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Automation: reserved for %1 (hatched)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Automation: %1 is in this block (solid)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Automation: an unknown occupant, no train can have reached it (cross-hatched); no automatic train enters it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Automation: %1 stopped by a fault (dotted); see the Automatic panel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No automation runs on this layout.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The block is reserved for %1: choose another block.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is in this block already: remove it first.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::PowerStatus</name>
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
        <source>Track power: not reported</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::ProblemBar</name>
    <message>
        <source>Show all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fold</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the whole message</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show only the first line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dismiss this message</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dismiss</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::ProgrammingPanel</name>
    <message>
        <source>(address below)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MM2 decoders can be written (CV 1–256) but not read back.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mfx: CV 1–1023 with an index (read 0–63, write 1–63), on either track.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SX1: values 1–5 (address, top speed, acceleration, pulse width, stop sections), programming track only.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DCC: CV 1–1023; read on the programming track, write on either track.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Searching the track for new mfx decoders…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Searching: %1 of %2 bits of the decoder&apos;s UID known (%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This address does not exist for the chosen protocol.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading CV %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writing CV %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No new mfx decoder answered. Decoders that are registered already take no part.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>found</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Found mfx decoder %1. Choose a SID and press Register; search again for more.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bound to SID %1, verifying…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>does not answer under SID %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>registered on SID %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CV %1.%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CV %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 = %2 (0x%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 written: %2, read back and verified.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 written: %2. Not verified: the decoder cannot be read back.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No value: the decoder did not answer the read (is it on the programming track?).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refused: the station could not write the CV.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refused by the station.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No answer from the station.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not sent: the station is not connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wait: the station is still busy with the last programming command.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Only MM2, DCC, mfx and SX1 decoders can be programmed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MM2 decoders cannot be read: the station can only write their CVs.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The CV must be between %1 and %2 for this protocol.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The mfx index must be between %1 and %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Only mfx CVs have an index.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SX1 decoders are programmed on the programming track only.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Programming modes are for DCC decoders only.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This DCC programming mode is reserved.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bit programming needs a bit position and value.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose a SID from 1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No station connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New mfx decoders</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CV programming</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Search</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The station searches the track for one mfx decoder that is not registered yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SID:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Register</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Binds the selected decoder to the SID, then checks that it answers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Locomotive:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Decoder:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CV:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Index:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Value:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Track:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DCC mode:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bit:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mfx SID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DCC</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MM2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SX1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>programming track</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>main track (write only)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>direct</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>register</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>set</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Registered mfx decoder %1 on SID %2. It is a locomotive of the list now: name it and save it there; search again for more.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::RoModuleDialog</name>
    <message>
        <source>Change flags at</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add RO module</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edit RO module</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>0 (the station&apos;s bus)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>29-bit (extended)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>11-bit (standard, CAN adapters only)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Request id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Answer id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Relays at</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Inputs at</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read inputs every</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RO modules name no ids and no register map; take them from the module&apos;s manual or its switches. The user guide (Help) lists Stellwerk&apos;s defaults.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>count</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The module needs a name.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Another module is called &quot;%1&quot;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Every id and address is a hexadecimal number.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Register addresses go up to 0xFFFF.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The module cannot be used so: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::RoModuleView</name>
    <message>
        <source>Relay %1 was not switched: the module does not answer.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The relays were not switched off: the module does not answer.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not switched: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Answers %1 · repeated %2 · timed out %3 · refused %4 · late or foreign %5 · unreadable %6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading the relays…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Online. A relay changes colour once the module confirmed it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Offline: the module does not answer. Relays and inputs are %1 until it answers again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Relays (click one to switch it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All relays off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Inputs</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::ScheduleDialog</name>
    <message>
        <source>Schedule changed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keep the changes to the schedule?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Schedule of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop (block)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dwell</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Add stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Remove stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move &amp;up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move &amp;down</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run in a &amp;loop (after the last stop, the first again)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> s</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::SignalGrid</name>
    <message>
        <source>on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2, waiting for the device to confirm the change</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::SpeedScale</name>
    <message>
        <source>%1 km/h</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::StartupProgress</name>
    <message>
        <source>Step %1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>file %1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 (%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 of %3 (%4)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::StatusPanel</name>
    <message>
        <source>Track current (main)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Track current (programming)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Track current</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Voltage</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Temperature</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1, article %2, version %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No device has described its readings yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>channel %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Overload on %1 (%2): the track power is off. Look for a short circuit or a derailed train, then switch the power on again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Settings</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::StopGoButton</name>
    <message>
        <source>STOP</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Track power is on. Press to switch it off: every train stops (Space)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TRACK POWER OFF · press to switch on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The layout is stopped: the station switched the track power off. Press to switch it on again (GO); trains resume their speeds.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TRAINS HALTED · press to go on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Every train was halted; the track still has power. Press to let them go on (GO).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>STOP · power not reported</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The station has not reported the track power (silent, reconnecting or not yet said). Press to switch it off anyway (Space).</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::StopKeyMenu</name>
    <message>
        <source>Extra STOP &amp;key</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>None (Space only)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::ThrottlePanel</name>
    <message>
        <source>Add throttle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open one more throttle (up to %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Alt+1…9: keyboard on a throttle · Up/Down or +/−: speed · R: direction · 0–9: F0–F9 · E: stop this loco · Space stays STOP for the layout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No station connected: throttles drive once a station is ready.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Alt+1…9: drive with the keyboard</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drive %1 (running)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drive %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No throttle open. Open one for a locomotive below, or with “Add throttle”.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::ThrottleTableModel</name>
    <message>
        <source>OpenRailCAN throttle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Z21 app or WLANmaus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>WiThrottle or Engine Driver</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kind</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Address</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drives</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Last message</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::ThrottleWidget</name>
    <message>
        <source>Choose a locomotive…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Locomotive 0x%1 (not on this station)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Locomotive 0x%1 (waiting for the station)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Alt+%1 puts the keyboard on this throttle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close this throttle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>—</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 km/h</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>◀ Backward</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forward ▶</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change direction (R); the station stops the locomotive first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop loco</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed: %1 % (Up/Down, +/-, PageUp/PageDown)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The station did not acknowledge the last command: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no locomotive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change locomotive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is running (%2). Drive %3 with this throttle instead?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 keeps running at its speed; this throttle no longer drives it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drive %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keep %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Emergency stop for this locomotive only (E); STOP in the toolbar stops the whole layout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The speed the station confirmed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Requested: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sent to the station; the number above changes when it confirms</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::TrackPlanPanel</name>
    <message>
        <source>Cannot open the layout: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>There is no track plan to export: connect to a station or open a layout first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot export the layout: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Page %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open layout...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the track plan of a CS2 configuration folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Station&apos;s plan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write the layout as a CS2 configuration folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No track plan: connect to a station or open a CS2 layout folder.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Files: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Live from the station</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>The layout&apos;s files disagree in %n place(s):</source>
        <translation>
            <numerusform>The layout&apos;s files disagree in %n place:</numerusform>
            <numerusform>The layout&apos;s files disagree in %n places:</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>... and %n more.</source>
        <translation>
            <numerusform>... and %n more.</numerusform>
            <numerusform>... and %n more.</numerusform>
        </translation>
    </message>
    <message>
        <source>Export layout...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Locomotive on it: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%1 is missing: the %n page file(s) found in gleisbilder/ are shown in the order of their names. Export the layout to write a new gleisbild.cs2 for them.</source>
        <translation>
            <numerusform>%1 is missing: the %n page file found in gleisbilder/ is shown. Export the layout to write a new gleisbild.cs2 for it.</numerusform>
            <numerusform>%1 is missing: the %n page files found in gleisbilder/ are shown in the order of their names. Export the layout to write a new gleisbild.cs2 for them.</numerusform>
        </translation>
    </message>
    <message>
        <source>This page has nothing to show: its name cannot be a file name, so no file was looked for.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This page has nothing to show: its file %1 is missing.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This page has nothing to show: its file %1 could not be read.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Block %1 &apos;%2&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Problem: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Block %1 &apos;%2&apos;...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Blocks</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Outline each block with its name, and list and mark the problems of the drawing; then a click on a block&apos;s track says where it leads</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Station memory %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Station memory %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Announced on the station&apos;s bus: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Place a train in %1...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove %1 from %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drop the locomotive on a block&apos;s track to place it there.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::TrafficStatus</name>
    <message>
        <source>Frames in %1 · out %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Frames received from and sent to the station since connecting; %1 malformed, %2 dropped, %3 reconnects</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::TurnoutKey</name>
    <message>
        <source>part of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch %1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2), address %3: %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Address %1 has no article; it switches as an MM2 address</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Address %1 belongs to %2, which starts on %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switching: waiting for the station to confirm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The station did not confirm the last switching</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no article</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not known</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch %1 to another position</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stellwerk::ui::TurnoutPanel</name>
    <message>
        <source>Articles on the keyboard: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Article %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Page %1: %2–%3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The keyboard appears when a station is connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Previous page (Page Up)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Next page (Page Down)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keyboard page: 16 addresses each, as on the Central Station</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Articles on the keyboard: %1 · positions %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
