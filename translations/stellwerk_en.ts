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
    <name>stellwerk::ui::BusMonitorModel</name>
    <message>
        <source>received</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>sent</source>
        <translation type="unfinished"></translation>
    </message>
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
    <message numerus="yes">
        <source>%Ln line(s) held no frame, the first one is line %1.</source>
        <translation>
            <numerusform>%Ln line held no frame, it is line %1.</numerusform>
            <numerusform>%Ln lines held no frame, the first one is line %1.</numerusform>
        </translation>
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
        <source>%Ln frame(s) received</source>
        <translation>
            <numerusform>%Ln frame received</numerusform>
            <numerusform>%Ln frames received</numerusform>
        </translation>
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
        <source>Filter by message, Loc-ID or bytes, e.g. loco.speed or 0xC003</source>
        <translation type="unfinished"></translation>
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
        <source>Stop &amp;recording</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Record…</source>
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
        <source>Show the frames of a candump log file instead of the current ones</source>
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
</context>
<context>
    <name>stellwerk::ui::ConnectDialog</name>
    <message>
        <source>Connect to a station</source>
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
    <name>stellwerk::ui::GaugeWidget</name>
    <message>
        <source>%1: no answer to the last request, the value is old</source>
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
        <source>Space, Esc</source>
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
</context>
<context>
    <name>stellwerk::ui::StopGoButton</name>
    <message>
        <source>STOP</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>GO</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch the track power off: every train stops (Space or Escape)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch the track power on again</source>
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
</TS>
