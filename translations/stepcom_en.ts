<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
<context>
    <name>GivenFile</name>
    <message>
        <source>%1: no such file</source>
        <translation>%1: no such file</translation>
    </message>
    <message>
        <source>%1 is a folder, not a file</source>
        <translation>%1 is a folder, not a file</translation>
    </message>
    <message>
        <source>%1 cannot be read: %2</source>
        <translation>%1 cannot be read: %2</translation>
    </message>
    <message>
        <source>%1 is neither a StepCom profile, a sequence, a session log nor a support bundle: StepCom opens those.</source>
        <translation>%1 is neither a StepCom profile, a sequence, a session log nor a support bundle: StepCom opens those.</translation>
    </message>
</context>
<context>
    <name>stepcom</name>
    <message>
        <source>Commissioning window for a 2-axis stepper controller (Modbus RTU/TCP).</source>
        <translation>Commissioning window for a 2-axis stepper controller (Modbus RTU/TCP).</translation>
    </message>
    <message>
        <source>Start connected to the built-in simulator.</source>
        <translation>Start connected to the built-in simulator.</translation>
    </message>
    <message>
        <source>Connect to this serial port at start.</source>
        <translation>Connect to this serial port at start.</translation>
    </message>
    <message>
        <source>path</source>
        <translation>path</translation>
    </message>
    <message>
        <source>Connect to this Modbus TCP gateway at start.</source>
        <translation>Connect to this Modbus TCP gateway at start.</translation>
    </message>
    <message>
        <source>host:port</source>
        <translation>host:port</translation>
    </message>
    <message>
        <source>Baud rate (default 9600).</source>
        <translation>Baud rate (default 9600).</translation>
    </message>
    <message>
        <source>rate</source>
        <translation>rate</translation>
    </message>
    <message>
        <source>Device id (default 1).</source>
        <translation>Device id (default 1).</translation>
    </message>
    <message>
        <source>id</source>
        <translation>id</translation>
    </message>
    <message>
        <source>Connect at start to this RS-485/Ethernet converter in transparent mode (RTU over TCP).</source>
        <translation>Connect at start to this RS-485/Ethernet converter in transparent mode (RTU over TCP).</translation>
    </message>
    <message>
        <source>The adapter echoes what it sends.</source>
        <translation>The adapter echoes what it sends.</translation>
    </message>
    <message>
        <source>Parity: none, even or odd (default none).</source>
        <translation>Parity: none, even or odd (default none).</translation>
    </message>
    <message>
        <source>parity</source>
        <translation>parity</translation>
    </message>
    <message>
        <source>A profile to edit without a controller, or a session log or support bundle to replay.</source>
        <translation>A profile to edit without a controller, or a session log or support bundle to replay.</translation>
    </message>
    <message>
        <source>Start the built-in simulator from the factory again: forget what it saved to flash.</source>
        <translation>Start the built-in simulator from the factory again: forget what it saved to flash.</translation>
    </message>
    <message>
        <source>Start the phone pendant at launch (watch only) on this port, 0 for any free one; prints its address.</source>
        <translation>Start the phone pendant at launch (watch only) on this port, 0 for any free one; prints its address.</translation>
    </message>
    <message>
        <source>[address:]port</source>
        <translation>[address:]port</translation>
    </message>
    <message>
        <source>Allow jogging from the pendant from launch.</source>
        <translation>Allow jogging from the pendant from launch.</translation>
    </message>
    <message>
        <source>With --port: listen only, another master drives the line (nothing is sent but the E-STOP).</source>
        <translation>With --port: listen only, another master drives the line (nothing is sent but the E-STOP).</translation>
    </message>
    <message>
        <source>--listen needs --port</source>
        <translation>--listen needs --port</translation>
    </message>
    <message>
        <source>With --sim: the simulated machine&apos;s mechanics from this machine file (stalls, backlash, switches; default: the setting simulator/machineFile).</source>
        <translation>With --sim: the simulated machine&apos;s mechanics from this machine file (stalls, backlash, switches; default: the setting simulator/machineFile).</translation>
    </message>
    <message>
        <source>file</source>
        <translation>file</translation>
    </message>
    <message>
        <source>%1 is above pull_out_rpm (%2): a motor cannot start faster than it runs</source>
        <translation>%1 is above pull_out_rpm (%2): a motor cannot start faster than it runs</translation>
    </message>
    <message>
        <source>%1 is not above negative_switch_mm (%2)</source>
        <translation>%1 is not above negative_switch_mm (%2)</translation>
    </message>
    <message>
        <source>%1 is beyond the hard stops</source>
        <translation>%1 is beyond the hard stops</translation>
    </message>
</context>
<context>
    <name>stepcom-sim</name>
    <message>
        <source>A simulated 2-axis stepper controller speaking Modbus RTU on a pseudo-terminal and/or Modbus TCP. Without --pty or --tcp it serves a pseudo-terminal.</source>
        <translation>A simulated 2-axis stepper controller speaking Modbus RTU on a pseudo-terminal and/or Modbus TCP. Without --pty or --tcp it serves a pseudo-terminal.</translation>
    </message>
    <message>
        <source>Read console commands from standard input even when it is not a terminal.</source>
        <translation>Read console commands from standard input even when it is not a terminal.</translation>
    </message>
    <message>
        <source>stepcom-sim: %1</source>
        <translation>stepcom-sim: %1</translation>
    </message>
    <message>
        <source>port hung up</source>
        <translation>port hung up</translation>
    </message>
    <message>
        <source>port back: %1</source>
        <translation>port back: %1</translation>
    </message>
    <message>
        <source>stepcom-sim %1: device id %2, %3 baud, %4 motors</source>
        <translation>stepcom-sim %1: device id %2, %3 baud, %4 motors</translation>
    </message>
    <message>
        <source>type &apos;help&apos; for the console commands</source>
        <translation>type &apos;help&apos; for the console commands</translation>
    </message>
    <message>
        <source>%1 controllers on the line, ids %2 (the console acts on the first)</source>
        <translation>%1 controllers on the line, ids %2 (the console acts on the first)</translation>
    </message>
    <message>
        <source>line %1 sent %2 bytes</source>
        <translation>line %1 sent %2 bytes</translation>
    </message>
</context>
<context>
    <name>stepcom::AboutBox</name>
    <message>
        <source>About this page</source>
        <translation>About this page</translation>
    </message>
    <message>
        <source>Show or hide what this page is for (F1: the user guide)</source>
        <translation>Show or hide what this page is for (F1: the user guide)</translation>
    </message>
    <message>
        <source>More in the user guide (F1)</source>
        <translation>More in the user guide (F1)</translation>
    </message>
</context>
<context>
    <name>stepcom::AnswerCheck</name>
    <message>
        <source>function %1 answered a request of function %2</source>
        <translation>function %1 answered a request of function %2</translation>
    </message>
    <message>
        <source>exception answer of %1 bytes</source>
        <translation>exception answer of %1 bytes</translation>
    </message>
    <message>
        <source>FC03 answer carried %1 registers, %2 were asked for</source>
        <translation>FC03 answer carried %1 registers, %2 were asked for</translation>
    </message>
    <message>
        <source>FC%1 answer for 0x%2 = 0x%3, the request wrote 0x%4 = 0x%5</source>
        <translation>FC%1 answer for 0x%2 = 0x%3, the request wrote 0x%4 = 0x%5</translation>
    </message>
    <message>
        <source>FC10 answer for %1 registers at 0x%2, the request wrote %3 at 0x%4</source>
        <translation>FC10 answer for %1 registers at 0x%2, the request wrote %3 at 0x%4</translation>
    </message>
</context>
<context>
    <name>stepcom::ApplyToDevicesDialog</name>
    <message>
        <source>&amp;Compare the ticked devices</source>
        <translation>&amp;Compare the ticked devices</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Close</translation>
    </message>
    <message>
        <source>Apply %1 to several devices</source>
        <translation>Apply %1 to several devices</translation>
    </message>
    <message>
        <source>Tick the devices, compare, then uncheck what is not to be written. Each device&apos;s settings are saved as a backup before anything is written to it; every value written is read back. Device id and baud rate are never applied to several devices: one id for all would make them collide.</source>
        <translation>Tick the devices, compare, then uncheck what is not to be written. Each device&apos;s settings are saved as a backup before anything is written to it; every value written is read back. Device id and baud rate are never applied to several devices: one id for all would make them collide.</translation>
    </message>
    <message>
        <source>id %1</source>
        <translation>id %1</translation>
    </message>
    <message>
        <source>id %1 (%2)</source>
        <translation>id %1 (%2)</translation>
    </message>
    <message>
        <source>Device / parameter</source>
        <translation>Device / parameter</translation>
    </message>
    <message>
        <source>Device holds</source>
        <translation>Device holds</translation>
    </message>
    <message>
        <source>Profile</source>
        <translation>Profile</translation>
    </message>
    <message>
        <source>Done:</source>
        <translation>Done:</translation>
    </message>
    <message>
        <source>Done, not everywhere:</source>
        <translation>Done, not everywhere:</translation>
    </message>
    <message numerus="yes">
        <source>Reading %n device(s)…</source>
        <translation>
            <numerusform>Reading %n device…</numerusform>
            <numerusform>Reading %n devices…</numerusform>
        </translation>
    </message>
    <message>
        <source>Nothing has been written yet.</source>
        <translation>Nothing has been written yet.</translation>
    </message>
    <message>
        <source>Nothing to write: the devices hold the profile&apos;s values or could not be read.</source>
        <translation>Nothing to write: the devices hold the profile&apos;s values or could not be read.</translation>
    </message>
    <message>
        <source>Writing…</source>
        <translation>Writing…</translation>
    </message>
    <message>
        <source>Writing… this window stays open until every device has its result. E-STOP (F12) stops what is left.</source>
        <translation>Writing… this window stays open until every device has its result. E-STOP (F12) stops what is left.</translation>
    </message>
    <message numerus="yes">
        <source>&amp;Write %n value(s) to %1 device(s)</source>
        <translation>
            <numerusform>&amp;Write %n value to %1 device</numerusform>
            <numerusform>&amp;Write %n values to %1 devices</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Write</source>
        <translation>&amp;Write</translation>
    </message>
</context>
<context>
    <name>stepcom::AxisProof</name>
    <message>
        <source>Motor %1: reading its values</source>
        <translation>Motor %1: reading its values</translation>
    </message>
    <message>
        <source>cycles must be 1 to 1000, not %1</source>
        <translation>cycles must be 1 to 1000, not %1</translation>
    </message>
    <message>
        <source>the distance must be above 0 and within the single move&apos;s range, not %1</source>
        <translation>the distance must be above 0 and within the single move&apos;s range, not %1</translation>
    </message>
    <message>
        <source>Motor %1: the test speed %2 rpm: %3</source>
        <translation>Motor %1: the test speed %2 rpm: %3</translation>
    </message>
    <message>
        <source>Motor %1: the test acceleration %2: %3</source>
        <translation>Motor %1: the test acceleration %2: %3</translation>
    </message>
    <message>
        <source>The test needs the travel from the home switch to %1 %2 past it: %3</source>
        <translation>The test needs the travel from the home switch to %1 %2 past it: %3</translation>
    </message>
    <message>
        <source>Motor %1 stands at its lower travel limit: the home switch beyond it cannot be searched for</source>
        <translation>Motor %1 stands at its lower travel limit: the home switch beyond it cannot be searched for</translation>
    </message>
    <message>
        <source>Motor %1: the lost-step test</source>
        <translation>Motor %1: the lost-step test</translation>
    </message>
    <message>
        <source>  reference: the home switch on IN%1, approached in the negative direction (up to %2 %3) at %4 rpm, %5</source>
        <translation>  reference: the home switch on IN%1, approached in the negative direction (up to %2 %3) at %4 rpm, %5</translation>
    </message>
    <message>
        <source>from where the last test found it</source>
        <translation>from where the last test found it</translation>
    </message>
    <message>
        <source>twice, to measure its repeatability</source>
        <translation>twice, to measure its repeatability</translation>
    </message>
    <message>
        <source>  then %1 cycle(s) of %2 %3 out at %4 rpm (acceleration %5 %6) and back at %7 rpm, a reference, the same out at %7 rpm and back at %4 rpm, a reference</source>
        <translation>  then %1 cycle(s) of %2 %3 out at %4 rpm (acceleration %5 %6) and back at %7 rpm, a reference, the same out at %7 rpm and back at %4 rpm, a reference</translation>
    </message>
    <message>
        <source>  travel: from the home switch to %1 %2 past it</source>
        <translation>  travel: from the home switch to %1 %2 past it</translation>
    </message>
    <message>
        <source>  afterwards: speed %1 rpm and acceleration %2 %3 put back and verified</source>
        <translation>  afterwards: speed %1 rpm and acceleration %2 %3 put back and verified</translation>
    </message>
    <message>
        <source>Motor %1: reference 1 of 2 on the home switch</source>
        <translation>Motor %1: reference 1 of 2 on the home switch</translation>
    </message>
    <message>
        <source>Motor %1: reference 2 of 2 on the home switch</source>
        <translation>Motor %1: reference 2 of 2 on the home switch</translation>
    </message>
    <message>
        <source>Motor %1: the reference on the home switch failed: %2</source>
        <translation>Motor %1: the reference on the home switch failed: %2</translation>
    </message>
    <message>
        <source>Motor %1: %2 cycle(s) out at %3 rpm, back at %4 rpm</source>
        <translation>Motor %1: %2 cycle(s) out at %3 rpm, back at %4 rpm</translation>
    </message>
    <message>
        <source>Motor %1: reference on the home switch</source>
        <translation>Motor %1: reference on the home switch</translation>
    </message>
    <message>
        <source>Stopped before anything moved</source>
        <translation>Stopped before anything moved</translation>
    </message>
    <message>
        <source>Motor %1 %2 at %3 rpm: %4 %5 off after the moves out, %6 %5 after the moves back (switch repeatability %7 %5, 4 full steps %8 %5)</source>
        <translation>Motor %1 %2 at %3 rpm: %4 %5 off after the moves out, %6 %5 after the moves back (switch repeatability %7 %5, 4 full steps %8 %5)</translation>
    </message>
    <message>
        <source>The switch did not repeat well enough to tell a loss of 4 full steps.</source>
        <translation>The switch did not repeat well enough to tell a loss of 4 full steps.</translation>
    </message>
</context>
<context>
    <name>stepcom::BacklashTest</name>
    <message>
        <source>cycles must be 1 to 100, not %1</source>
        <translation>cycles must be 1 to 100, not %1</translation>
    </message>
    <message>
        <source>the distance must be above 0 and within the single move&apos;s range, not %1</source>
        <translation>the distance must be above 0 and within the single move&apos;s range, not %1</translation>
    </message>
    <message>
        <source>The test moves %1 %2 either way: %3</source>
        <translation>The test moves %1 %2 either way: %3</translation>
    </message>
    <message>
        <source>Motor %1: the backlash test with a dial gauge on the carriage</source>
        <translation>Motor %1: the backlash test with a dial gauge on the carriage</translation>
    </message>
    <message>
        <source>  back %1 %2 and on %1 %2 (the approach), then %3 time(s) on %1 %2 and back %1 %2, at %4 rpm; the gauge is read %5 times</source>
        <translation>  back %1 %2 and on %1 %2 (the approach), then %3 time(s) on %1 %2 and back %1 %2, at %4 rpm; the gauge is read %5 times</translation>
    </message>
    <message>
        <source>  afterwards: speed %1 rpm put back and verified</source>
        <translation>  afterwards: speed %1 rpm put back and verified</translation>
    </message>
    <message>
        <source>Motor %1: the approach</source>
        <translation>Motor %1: the approach</translation>
    </message>
    <message>
        <source>after the approach</source>
        <translation>after the approach</translation>
    </message>
    <message>
        <source>Motor %1: backlash %2 %3 (spread %4 %3 over %5 reversals)</source>
        <translation>Motor %1: backlash %2 %3 (spread %4 %3 over %5 reversals)</translation>
    </message>
    <message>
        <source>It is more than the count&apos;s resolution: position the axis from one side (approach every point in the same direction)</source>
        <translation>It is more than the count&apos;s resolution: position the axis from one side (approach every point in the same direction)</translation>
    </message>
    <message>
        <source>Motor %1: move %2 of %3</source>
        <translation>Motor %1: move %2 of %3</translation>
    </message>
    <message>
        <source>after moving on by %1</source>
        <translation>after moving on by %1</translation>
    </message>
    <message>
        <source>after moving back by %1</source>
        <translation>after moving back by %1</translation>
    </message>
    <message>
        <source>Stopped: no more readings</source>
        <translation>Stopped: no more readings</translation>
    </message>
</context>
<context>
    <name>stepcom::BackupGuard</name>
    <message>
        <source>No backup of the controller&apos;s settings could be saved (%1): %2 was not done</source>
        <translation>No backup of the controller&apos;s settings could be saved (%1): %2 was not done</translation>
    </message>
    <message>
        <source>Backup of the controller&apos;s settings before %1: %2</source>
        <translation>Backup of the controller&apos;s settings before %1: %2</translation>
    </message>
</context>
<context>
    <name>stepcom::BackupStore</name>
    <message>
        <source>apply a profile</source>
        <translation>apply a profile</translation>
    </message>
    <message>
        <source>factory reset</source>
        <translation>factory reset</translation>
    </message>
    <message>
        <source>save to flash</source>
        <translation>save to flash</translation>
    </message>
    <message>
        <source>device id change</source>
        <translation>device id change</translation>
    </message>
    <message>
        <source>baud rate change</source>
        <translation>baud rate change</translation>
    </message>
    <message>
        <source>cannot create the backup folder %1</source>
        <translation>cannot create the backup folder %1</translation>
    </message>
    <message>
        <source>no settings to back up: the controller was not read</source>
        <translation>no settings to back up: the controller was not read</translation>
    </message>
    <message>
        <source>Backup before %1</source>
        <translation>Backup before %1</translation>
    </message>
</context>
<context>
    <name>stepcom::BackupsDialog</name>
    <message>
        <source>cannot be read: %1</source>
        <translation>cannot be read: %1</translation>
    </message>
    <message>
        <source>Backups</source>
        <translation>Backups</translation>
    </message>
    <message>
        <source>StepCom saves the controller&apos;s settings here before every apply, factory reset, save to flash and id or baud change: %1</source>
        <translation>StepCom saves the controller&apos;s settings here before every apply, factory reset, save to flash and id or baud change: %1</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Time</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Device</translation>
    </message>
    <message>
        <source>What happened after</source>
        <translation>What happened after</translation>
    </message>
    <message>
        <source>Restore…</source>
        <translation>Restore…</translation>
    </message>
    <message>
        <source>Compare the backup with the controller and apply what you check</source>
        <translation>Compare the backup with the controller and apply what you check</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Close</translation>
    </message>
</context>
<context>
    <name>stepcom::BuiltinSimulator</name>
    <message>
        <source>cannot remove %1: %2</source>
        <translation>cannot remove %1: %2</translation>
    </message>
    <message>
        <source>cannot make the folder of %1</source>
        <translation>cannot make the folder of %1</translation>
    </message>
    <message>
        <source>%1 (the simulator runs as the ideal machine)</source>
        <translation>%1 (the simulator runs as the ideal machine)</translation>
    </message>
</context>
<context>
    <name>stepcom::BusActions</name>
    <message>
        <source>Assign device ids…</source>
        <translation>Assign device ids…</translation>
    </message>
    <message>
        <source>Give each controller of a new line its own id, one controller at a time</source>
        <translation>Give each controller of a new line its own id, one controller at a time</translation>
    </message>
    <message>
        <source>the built-in simulator is reset to the factory</source>
        <translation>the built-in simulator is reset to the factory</translation>
    </message>
    <message>
        <source>The built-in simulator could not be reset: %1</source>
        <translation>The built-in simulator could not be reset: %1</translation>
    </message>
    <message>
        <source>The built-in simulator is back at the factory: id 1, 9600 baud, nothing saved. Connect to it again to start it.</source>
        <translation>The built-in simulator is back at the factory: id 1, 9600 baud, nothing saved. Connect to it again to start it.</translation>
    </message>
    <message>
        <source>Reset the built-in simulator to factory</source>
        <translation>Reset the built-in simulator to factory</translation>
    </message>
    <message>
        <source>Forget what the built-in simulator saved to flash: it starts again as it leaves the factory</source>
        <translation>Forget what the built-in simulator saved to flash: it starts again as it leaves the factory</translation>
    </message>
</context>
<context>
    <name>stepcom::BusDump</name>
    <message>
        <source>%1: no such folder</source>
        <translation>%1: no such folder</translation>
    </message>
    <message>
        <source>%1 is not a folder</source>
        <translation>%1 is not a folder</translation>
    </message>
    <message>
        <source>%1: the folder cannot be written to</source>
        <translation>%1: the folder cannot be written to</translation>
    </message>
    <message>
        <source>Controller id %1</source>
        <translation>Controller id %1</translation>
    </message>
</context>
<context>
    <name>stepcom::BusScanDialog</name>
    <message>
        <source>Scan bus</source>
        <translation>Scan bus</translation>
    </message>
    <message>
        <source>Where</source>
        <translation>Where</translation>
    </message>
    <message>
        <source>Port:</source>
        <translation>Port:</translation>
    </message>
    <message>
        <source>What to try</source>
        <translation>What to try</translation>
    </message>
    <message>
        <source>&amp;Baud rates:</source>
        <translation>&amp;Baud rates:</translation>
    </message>
    <message>
        <source>Try this baud rate (register 40213; the factory setting is 9600)</source>
        <translation>Try this baud rate (register 40213; the factory setting is 9600)</translation>
    </message>
    <message>
        <source>Device &amp;ids:</source>
        <translation>Device &amp;ids:</translation>
    </message>
    <message>
        <source>to</source>
        <translation>to</translation>
    </message>
    <message>
        <source>First device id to try (register 40212; factory setting 1)</source>
        <translation>First device id to try (register 40212; factory setting 1)</translation>
    </message>
    <message>
        <source>Last device id to try; 247 is the highest standard Modbus address</source>
        <translation>Last device id to try; 247 is the highest standard Modbus address</translation>
    </message>
    <message>
        <source>Probe &amp;timeout:</source>
        <translation>Probe &amp;timeout:</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>Stop at the &amp;first controller found</source>
        <translation>Stop at the &amp;first controller found</translation>
    </message>
    <message>
        <source>Finish as soon as one controller answers</source>
        <translation>Finish as soon as one controller answers</translation>
    </message>
    <message>
        <source>&amp;Start</source>
        <translation>&amp;Start</translation>
    </message>
    <message>
        <source>Start the scan; it only reads, nothing is written</source>
        <translation>Start the scan; it only reads, nothing is written</translation>
    </message>
    <message>
        <source>&amp;Cancel</source>
        <translation>&amp;Cancel</translation>
    </message>
    <message>
        <source>Stop the scan now</source>
        <translation>Stop the scan now</translation>
    </message>
    <message>
        <source>Controllers found</source>
        <translation>Controllers found</translation>
    </message>
    <message>
        <source>Baud</source>
        <translation>Baud</translation>
    </message>
    <message>
        <source>Device id</source>
        <translation>Device id</translation>
    </message>
    <message>
        <source>Double-click a controller to connect to it</source>
        <translation>Double-click a controller to connect to it</translation>
    </message>
    <message>
        <source>C&amp;onnect</source>
        <translation>C&amp;onnect</translation>
    </message>
    <message>
        <source>Connect to the selected controller with its baud rate and id</source>
        <translation>Connect to the selected controller with its baud rate and id</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Close</translation>
    </message>
    <message>
        <source>even</source>
        <translation>even</translation>
    </message>
    <message>
        <source>odd</source>
        <translation>odd</translation>
    </message>
    <message>
        <source>none</source>
        <translation>none</translation>
    </message>
    <message>
        <source>%1:%2 (Modbus TCP)</source>
        <translation>%1:%2 (Modbus TCP)</translation>
    </message>
    <message numerus="yes">
        <source>%1, parity %2, %n stop bit(s)</source>
        <translation>
            <numerusform>%1, parity %2, %n stop bit</numerusform>
            <numerusform>%1, parity %2, %n stop bits</numerusform>
        </translation>
    </message>
    <message>
        <source>(no port chosen)</source>
        <translation>(no port chosen)</translation>
    </message>
    <message>
        <source>starting…</source>
        <translation>starting…</translation>
    </message>
    <message>
        <source>id %1 at %2 baud</source>
        <translation>id %1 at %2 baud</translation>
    </message>
    <message>
        <source>done</source>
        <translation>done</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>stopped</translation>
    </message>
    <message>
        <source>StepCom is connected on this port: the scan disconnects first.</source>
        <translation>StepCom is connected on this port: the scan disconnects first.</translation>
    </message>
    <message numerus="yes">
        <source>Scanning… %n controller(s) found so far.</source>
        <translation>
            <numerusform>Scanning… %n controller found so far.</numerusform>
            <numerusform>Scanning… %n controllers found so far.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Scan finished: %n controller(s) found. Select one and press Connect.</source>
        <translation>
            <numerusform>Scan finished: %n controller found. Select one and press Connect.</numerusform>
            <numerusform>Scan finished: %n controllers found. Select one and press Connect.</numerusform>
        </translation>
    </message>
    <message>
        <source>Scan finished: no controller answered. Check the power, the wiring (A and B swapped?) and the port.</source>
        <translation>Scan finished: no controller answered. Check the power, the wiring (A and B swapped?) and the port.</translation>
    </message>
    <message numerus="yes">
        <source>Scan cancelled: %n controller(s) found.</source>
        <translation>
            <numerusform>Scan cancelled: %n controller found.</numerusform>
            <numerusform>Scan cancelled: %n controllers found.</numerusform>
        </translation>
    </message>
    <message>
        <source>Scan stopped: %1</source>
        <translation>Scan stopped: %1</translation>
    </message>
    <message>
        <source>Choose at least one baud rate.</source>
        <translation>Choose at least one baud rate.</translation>
    </message>
    <message>
        <source>Scan stopped: StepCom connected on this port.</source>
        <translation>Scan stopped: StepCom connected on this port.</translation>
    </message>
    <message numerus="yes">
        <source>%n probe(s), at most about %1 s. A scan only reads; nothing is written.</source>
        <translation>
            <numerusform>%n probe, at most about %1 s. A scan only reads; nothing is written.</numerusform>
            <numerusform>%n probes, at most about %1 s. A scan only reads; nothing is written.</numerusform>
        </translation>
    </message>
    <message>
        <source>Controller</source>
        <translation>Controller</translation>
    </message>
    <message>
        <source>Scan finished: %1. Press Connect.</source>
        <translation>Scan finished: %1. Press Connect.</translation>
    </message>
    <message>
        <source>%1:%2 (RTU over TCP)</source>
        <translation>%1:%2 (RTU over TCP)</translation>
    </message>
    <message>
        <source>&amp;Add all found</source>
        <translation>&amp;Add all found</translation>
    </message>
    <message>
        <source>Put every controller found on the device list (View → Devices on the line)</source>
        <translation>Put every controller found on the device list (View → Devices on the line)</translation>
    </message>
    <message>
        <source>Every controller found is on the device list already.</source>
        <translation>Every controller found is on the device list already.</translation>
    </message>
    <message>
        <source>Added to the device list: id %1.</source>
        <translation>Added to the device list: id %1.</translation>
    </message>
    <message>
        <source>They answered at different baud rates; give them one baud rate (Device page or Device → Assign device ids…) before working with the list.</source>
        <translation>They answered at different baud rates; give them one baud rate (Device page or Device → Assign device ids…) before working with the list.</translation>
    </message>
    <message>
        <source>%1 (answered after %2 ms: connects with a %3 ms timeout)</source>
        <translation>%1 (answered after %2 ms: connects with a %3 ms timeout)</translation>
    </message>
    <message>
        <source>fitted to the baud</source>
        <translation>fitted to the baud</translation>
    </message>
    <message>
        <source>How long to wait for an answer from each id. Fitted to the baud: the frames, the controller&apos;s 35 ms answer delay and a USB adapter&apos;s latency (67 ms at 9600). A controller that answers later is still found by its late answer; give more for one that answers very slowly.</source>
        <translation>How long to wait for an answer from each id. Fitted to the baud: the frames, the controller&apos;s 35 ms answer delay and a USB adapter&apos;s latency (67 ms at 9600). A controller that answers later is still found by its late answer; give more for one that answers very slowly.</translation>
    </message>
</context>
<context>
    <name>stepcom::BusScanner</name>
    <message>
        <source>no baud rate to try</source>
        <translation>no baud rate to try</translation>
    </message>
    <message>
        <source>scan finished</source>
        <translation>scan finished</translation>
    </message>
    <message>
        <source>id %1 at %2 — %3</source>
        <translation>id %1 at %2 — %3</translation>
    </message>
    <message>
        <source>a device that refused the first register: %1</source>
        <translation>a device that refused the first register: %1</translation>
    </message>
    <message>
        <source>a %1-axis controller</source>
        <translation>a %1-axis controller</translation>
    </message>
    <message>
        <source>a controller</source>
        <translation>a controller</translation>
    </message>
    <message>
        <source>%1, step angle %2</source>
        <translation>%1, step angle %2</translation>
    </message>
    <message>
        <source>%1, step angles %2</source>
        <translation>%1, step angles %2</translation>
    </message>
    <message>
        <source> and </source>
        <translation> and </translation>
    </message>
    <message>
        <source> (only %1 of %2 motors answered)</source>
        <translation> (only %1 of %2 motors answered)</translation>
    </message>
    <message>
        <source>identify id %1</source>
        <translation>identify id %1</translation>
    </message>
    <message>
        <source>no device id to try</source>
        <translation>no device id to try</translation>
    </message>
    <message>
        <source>scan id %1 at %2</source>
        <translation>scan id %1 at %2</translation>
    </message>
</context>
<context>
    <name>stepcom::BusSweep</name>
    <message>
        <source>id %1 was not read: E-STOP</source>
        <translation>id %1 was not read: E-STOP</translation>
    </message>
</context>
<context>
    <name>stepcom::CertificateSection</name>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Commissioning checklist</source>
        <translation>Commissioning checklist</translation>
    </message>
    <message>
        <source>No commissioning checklist was recorded for this machine: this report shows settings, not tests.</source>
        <translation>No commissioning checklist was recorded for this machine: this report shows settings, not tests.</translation>
    </message>
    <message>
        <source>Checklist file: %1</source>
        <translation>Checklist file: %1</translation>
    </message>
    <message>
        <source>The checklist was last run with other settings (fingerprint %1); this report&apos;s settings have the fingerprint %2.</source>
        <translation>The checklist was last run with other settings (fingerprint %1); this report&apos;s settings have the fingerprint %2.</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Step</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Result</translation>
    </message>
    <message>
        <source>Measured</source>
        <translation>Measured</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Time</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>Note</translation>
    </message>
    <message>
        <source>%1 (attempt %2)</source>
        <translation>%1 (attempt %2)</translation>
    </message>
    <message>
        <source>Software travel limits</source>
        <translation>Software travel limits</translation>
    </message>
    <message>
        <source>StepCom&apos;s own limits for steps, moves to a position and jogs; not controller registers. The limit switches stay the machine&apos;s protection.</source>
        <translation>StepCom&apos;s own limits for steps, moves to a position and jogs; not controller registers. The limit switches stay the machine&apos;s protection.</translation>
    </message>
    <message>
        <source>Motor</source>
        <translation>Motor</translation>
    </message>
    <message>
        <source>Min</source>
        <translation>Min</translation>
    </message>
    <message>
        <source>Max</source>
        <translation>Max</translation>
    </message>
    <message>
        <source>open</source>
        <translation>open</translation>
    </message>
    <message>
        <source>Motor %1</source>
        <translation>Motor %1</translation>
    </message>
    <message>
        <source>Signatures</source>
        <translation>Signatures</translation>
    </message>
    <message>
        <source>Role</source>
        <translation>Role</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Signature</source>
        <translation>Signature</translation>
    </message>
    <message>
        <source>Date</source>
        <translation>Date</translation>
    </message>
    <message>
        <source>Commissioned by</source>
        <translation>Commissioned by</translation>
    </message>
    <message>
        <source>Accepted by (customer)</source>
        <translation>Accepted by (customer)</translation>
    </message>
    <message>
        <source>Read from StepCom&apos;s built-in simulator, not from a machine: nothing here can be signed for a machine.</source>
        <translation>Read from StepCom&apos;s built-in simulator, not from a machine: nothing here can be signed for a machine.</translation>
    </message>
</context>
<context>
    <name>stepcom::Checklist</name>
    <message>
        <source>%1: a result is passed, failed or skipped, not pending</source>
        <translation>%1: a result is passed, failed or skipped, not pending</translation>
    </message>
    <message>
        <source>%1: the attempt has no valid time</source>
        <translation>%1: the attempt has no valid time</translation>
    </message>
    <message>
        <source>%1: the note has %2 characters (at most %3)</source>
        <translation>%1: the note has %2 characters (at most %3)</translation>
    </message>
    <message>
        <source>%1: %2 measurements (at most %3)</source>
        <translation>%1: %2 measurements (at most %3)</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a measurement key (1-40 of a-z, 0-9, _ and .)</source>
        <translation>%1: &quot;%2&quot; is not a measurement key (1-40 of a-z, 0-9, _ and .)</translation>
    </message>
    <message>
        <source>%1: the measurement &quot;%2&quot; is too long</source>
        <translation>%1: the measurement &quot;%2&quot; is too long</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a step of this checklist</source>
        <translation>&quot;%1&quot; is not a step of this checklist</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a step of this checklist (%2 motor(s))</source>
        <translation>&quot;%1&quot; is not a step of this checklist (%2 motor(s))</translation>
    </message>
    <message>
        <source>%1: %2 attempts (at most %3)</source>
        <translation>%1: %2 attempts (at most %3)</translation>
    </message>
    <message>
        <source>%1: the attempts must be numbered upwards (found %2 after %3)</source>
        <translation>%1: the attempts must be numbered upwards (found %2 after %3)</translation>
    </message>
    <message>
        <source>Not started</source>
        <translation>Not started</translation>
    </message>
    <message>
        <source>In progress: not every step was run</source>
        <translation>In progress: not every step was run</translation>
    </message>
    <message>
        <source>Failed: at least one step failed</source>
        <translation>Failed: at least one step failed</translation>
    </message>
    <message>
        <source>Passed, with skipped steps</source>
        <translation>Passed, with skipped steps</translation>
    </message>
    <message>
        <source>Passed: every step passed</source>
        <translation>Passed: every step passed</translation>
    </message>
    <message>
        <source>%1 of %2 steps passed, %3 failed, %4 skipped, %5 not run</source>
        <translation>%1 of %2 steps passed, %3 failed, %4 skipped, %5 not run</translation>
    </message>
</context>
<context>
    <name>stepcom::ChecklistBacklashStep</name>
    <message>
        <source>Put the gauge on the carriage. Run it? The axis will move.</source>
        <translation>Put the gauge on the carriage. Run it? The axis will move.</translation>
    </message>
    <message>
        <source>Reading %1 of %2, %3: type what the gauge shows and press Enter.</source>
        <translation>Reading %1 of %2, %3: type what the gauge shows and press Enter.</translation>
    </message>
    <message>
        <source>&amp;Distance of each move:</source>
        <translation>&amp;Distance of each move:</translation>
    </message>
    <message>
        <source>C&amp;ycles:</source>
        <translation>C&amp;ycles:</translation>
    </message>
    <message>
        <source>Distance of each move</source>
        <translation>Distance of each move</translation>
    </message>
    <message>
        <source>Cycles</source>
        <translation>Cycles</translation>
    </message>
    <message>
        <source>Gauge: </source>
        <translation>Gauge: </translation>
    </message>
    <message>
        <source>Gauge reading</source>
        <translation>Gauge reading</translation>
    </message>
    <message>
        <source>Start the &amp;backlash test</source>
        <translation>Start the &amp;backlash test</translation>
    </message>
    <message>
        <source>&amp;Stop</source>
        <translation>&amp;Stop</translation>
    </message>
    <message>
        <source>&amp;Enter reading</source>
        <translation>&amp;Enter reading</translation>
    </message>
</context>
<context>
    <name>stepcom::ChecklistCalibrationStep</name>
    <message>
        <source>Moving…</source>
        <translation>Moving…</translation>
    </message>
    <message>
        <source>The pitch was not written.</source>
        <translation>The pitch was not written.</translation>
    </message>
    <message>
        <source>Passed: the corrected pitch is written and verified.</source>
        <translation>Passed: the corrected pitch is written and verified.</translation>
    </message>
    <message>
        <source>Passed: the axis moved what it was told; the pitch stays %1 %2.</source>
        <translation>Passed: the axis moved what it was told; the pitch stays %1 %2.</translation>
    </message>
    <message>
        <source>Write the corrected pitch %1 %2…</source>
        <translation>Write the corrected pitch %1 %2…</translation>
    </message>
    <message>
        <source>Measured ÷ commanded = %1: the pitch %2 %3 should be %4 %3.</source>
        <translation>Measured ÷ commanded = %1: the pitch %2 %3 should be %4 %3.</translation>
    </message>
    <message>
        <source>Commanded: </source>
        <translation>Commanded: </translation>
    </message>
    <message>
        <source>Measured: </source>
        <translation>Measured: </translation>
    </message>
    <message>
        <source>Move this distance</source>
        <translation>Move this distance</translation>
    </message>
    <message>
        <source>Propose the pitch</source>
        <translation>Propose the pitch</translation>
    </message>
    <message>
        <source>Commanded distance</source>
        <translation>Commanded distance</translation>
    </message>
    <message>
        <source>Measured distance</source>
        <translation>Measured distance</translation>
    </message>
</context>
<context>
    <name>stepcom::ChecklistDirectionStep</name>
    <message>
        <source>The direction register is not read yet.</source>
        <translation>The direction register is not read yet.</translation>
    </message>
    <message>
        <source>Moving…</source>
        <translation>Moving…</translation>
    </message>
    <message>
        <source>The direction register is written and verified. Repeat the step to confirm the axis now moves toward +.</source>
        <translation>The direction register is written and verified. Repeat the step to confirm the axis now moves toward +.</translation>
    </message>
    <message>
        <source>The direction register was not written.</source>
        <translation>The direction register was not written.</translation>
    </message>
    <message>
        <source>Passed: the axis moves toward + with the direction as configured.</source>
        <translation>Passed: the axis moves toward + with the direction as configured.</translation>
    </message>
    <message>
        <source>Flip the direction to %1…</source>
        <translation>Flip the direction to %1…</translation>
    </message>
    <message>
        <source>Failed: the axis moved toward −. Flip the direction register, then repeat the step.</source>
        <translation>Failed: the axis moved toward −. Flip the direction register, then repeat the step.</translation>
    </message>
    <message>
        <source>Move a small step</source>
        <translation>Move a small step</translation>
    </message>
    <message>
        <source>Yes, toward +</source>
        <translation>Yes, toward +</translation>
    </message>
    <message>
        <source>No, toward −</source>
        <translation>No, toward −</translation>
    </message>
    <message>
        <source>Small step distance</source>
        <translation>Small step distance</translation>
    </message>
</context>
<context>
    <name>stepcom::ChecklistFile</name>
    <message>
        <source>null</source>
        <translation>null</translation>
    </message>
    <message>
        <source>true/false</source>
        <translation>true/false</translation>
    </message>
    <message>
        <source>a number</source>
        <translation>a number</translation>
    </message>
    <message>
        <source>a text</source>
        <translation>a text</translation>
    </message>
    <message>
        <source>a list</source>
        <translation>a list</translation>
    </message>
    <message>
        <source>an object</source>
        <translation>an object</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>nothing</translation>
    </message>
    <message>
        <source>the file is empty</source>
        <translation>the file is empty</translation>
    </message>
    <message>
        <source>the file is %1 bytes: far too large for a checklist</source>
        <translation>the file is %1 bytes: far too large for a checklist</translation>
    </message>
    <message>
        <source>not valid JSON at line %1, column %2: %3</source>
        <translation>not valid JSON at line %1, column %2: %3</translation>
    </message>
    <message>
        <source>the file holds a JSON list, not a checklist</source>
        <translation>the file holds a JSON list, not a checklist</translation>
    </message>
    <message>
        <source>… and %1 more problems</source>
        <translation>… and %1 more problems</translation>
    </message>
    <message>
        <source>%1unknown field &quot;%2&quot; (allowed: %3)</source>
        <translation>%1unknown field &quot;%2&quot; (allowed: %3)</translation>
    </message>
    <message>
        <source>%1&quot;%2&quot; must be a text, found %3</source>
        <translation>%1&quot;%2&quot; must be a text, found %3</translation>
    </message>
    <message>
        <source>this is a profile, not a checklist</source>
        <translation>this is a profile, not a checklist</translation>
    </message>
    <message>
        <source>not a StepCom checklist: &quot;format&quot; must be &quot;%1&quot;</source>
        <translation>not a StepCom checklist: &quot;format&quot; must be &quot;%1&quot;</translation>
    </message>
    <message>
        <source>checklist schema %1 is newer than this StepCom reads (%2): update StepCom</source>
        <translation>checklist schema %1 is newer than this StepCom reads (%2): update StepCom</translation>
    </message>
    <message>
        <source>&quot;schema&quot; must be %1</source>
        <translation>&quot;schema&quot; must be %1</translation>
    </message>
    <message>
        <source>the checklist is for register map &quot;%1&quot;, but this map is &quot;%2&quot;</source>
        <translation>the checklist is for register map &quot;%1&quot;, but this map is &quot;%2&quot;</translation>
    </message>
    <message>
        <source>&quot;machine&quot; and &quot;settingsFingerprint&quot; hold at most 200 characters</source>
        <translation>&quot;machine&quot; and &quot;settingsFingerprint&quot; hold at most 200 characters</translation>
    </message>
    <message>
        <source>&quot;steps&quot; must be a list, found %1</source>
        <translation>&quot;steps&quot; must be a list, found %1</translation>
    </message>
    <message>
        <source>step %1</source>
        <translation>step %1</translation>
    </message>
    <message>
        <source>%1: must be an object, found %2</source>
        <translation>%1: must be an object, found %2</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; appears more than once</source>
        <translation>%1: &quot;%2&quot; appears more than once</translation>
    </message>
    <message>
        <source>%1: &quot;attempts&quot; must be a list, found %2</source>
        <translation>%1: &quot;attempts&quot; must be a list, found %2</translation>
    </message>
    <message>
        <source>%1: &quot;attempt&quot; must be a whole number from 1</source>
        <translation>%1: &quot;attempt&quot; must be a whole number from 1</translation>
    </message>
    <message>
        <source>%1: &quot;result&quot; must be passed, failed or skipped, found &quot;%2&quot;</source>
        <translation>%1: &quot;result&quot; must be passed, failed or skipped, found &quot;%2&quot;</translation>
    </message>
    <message>
        <source>%1: &quot;time&quot; is not a date and time (2024-05-31T14:02:00Z): &quot;%2&quot;</source>
        <translation>%1: &quot;time&quot; is not a date and time (2024-05-31T14:02:00Z): &quot;%2&quot;</translation>
    </message>
    <message>
        <source>%1: &quot;measurements&quot; must be a list, found %2</source>
        <translation>%1: &quot;measurements&quot; must be a list, found %2</translation>
    </message>
    <message>
        <source>no register map to check the checklist against</source>
        <translation>no register map to check the checklist against</translation>
    </message>
    <message>
        <source>%1: no such file</source>
        <translation>%1: no such file</translation>
    </message>
    <message>
        <source>%1: %2 bytes, far too large for a checklist</source>
        <translation>%1: %2 bytes, far too large for a checklist</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>cannot write %1: %2</translation>
    </message>
</context>
<context>
    <name>stepcom::ChecklistFlashStep</name>
    <message>
        <source>Not connected: nothing was sent.</source>
        <translation>Not connected: nothing was sent.</translation>
    </message>
    <message>
        <source>Not every setting is read yet (%1): read all first.</source>
        <translation>Not every setting is read yet (%1): read all first.</translation>
    </message>
    <message>
        <source>Saving to flash…</source>
        <translation>Saving to flash…</translation>
    </message>
    <message>
        <source>Failed: the save to flash was not done (see the messages).</source>
        <translation>Failed: the save to flash was not done (see the messages).</translation>
    </message>
    <message numerus="yes">
        <source>%n setting(s) differ</source>
        <translation>
            <numerusform>%n setting differ</numerusform>
            <numerusform>%n settings differ</numerusform>
        </translation>
    </message>
    <message>
        <source>Failed: after the save these settings read back differently: %1</source>
        <translation>Failed: after the save these settings read back differently: %1</translation>
    </message>
    <message>
        <source>Failed: the settings could not be read back: %1</source>
        <translation>Failed: the settings could not be read back: %1</translation>
    </message>
    <message numerus="yes">
        <source>%n setting(s) read back unchanged</source>
        <translation>
            <numerusform>%n setting read back unchanged</numerusform>
            <numerusform>%n settings read back unchanged</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Passed: saved to flash, and all %n setting(s) read back unchanged.</source>
        <translation>
            <numerusform>Passed: saved to flash, and all %n setting read back unchanged.</numerusform>
            <numerusform>Passed: saved to flash, and all %n settings read back unchanged.</numerusform>
        </translation>
    </message>
    <message>
        <source>Save to flash and read back</source>
        <translation>Save to flash and read back</translation>
    </message>
</context>
<context>
    <name>stepcom::ChecklistInputStep</name>
    <message>
        <source>The input setting is written and verified. Repeat the step to confirm.</source>
        <translation>The input setting is written and verified. Repeat the step to confirm.</translation>
    </message>
    <message>
        <source>The input setting was not written.</source>
        <translation>The input setting was not written.</translation>
    </message>
    <message>
        <source>The inputs are not known yet: connect and wait for the status.</source>
        <translation>The inputs are not known yet: connect and wait for the status.</translation>
    </message>
    <message>
        <source>Watching the inputs: press the %1 of motor %2 now, let go, then click Done.</source>
        <translation>Watching the inputs: press the %1 of motor %2 now, let go, then click Done.</translation>
    </message>
    <message>
        <source>Write the fix (%1)…</source>
        <translation>Write the fix (%1)…</translation>
    </message>
    <message>
        <source>Press it now</source>
        <translation>Press it now</translation>
    </message>
    <message>
        <source>Done</source>
        <translation>Done</translation>
    </message>
</context>
<context>
    <name>stepcom::ChecklistMotionStep</name>
    <message>
        <source>Not connected: nothing was sent.</source>
        <translation>Not connected: nothing was sent.</translation>
    </message>
    <message>
        <source>Nothing to run: the homing order is empty, every motor runs, or the path&apos;s registers are not read yet.</source>
        <translation>Nothing to run: the homing order is empty, every motor runs, or the path&apos;s registers are not read yet.</translation>
    </message>
    <message>
        <source>Running…</source>
        <translation>Running…</translation>
    </message>
    <message>
        <source>The command was not acknowledged: nothing moved.</source>
        <translation>The command was not acknowledged: nothing moved.</translation>
    </message>
    <message>
        <source>Home motor %1</source>
        <translation>Home motor %1</translation>
    </message>
    <message>
        <source>Home in order</source>
        <translation>Home in order</translation>
    </message>
    <message>
        <source>Run the test</source>
        <translation>Run the test</translation>
    </message>
    <message>
        <source>The configured arc</source>
        <translation>The configured arc</translation>
    </message>
    <message>
        <source>The configured line</source>
        <translation>The configured line</translation>
    </message>
</context>
<context>
    <name>stepcom::ChecklistPage</name>
    <message>
        <source>Commissioning checklist</source>
        <translation>Commissioning checklist</translation>
    </message>
    <message>
        <source>The checklist file %1 cannot be used, and nothing is saved over it: %2</source>
        <translation>The checklist file %1 cannot be used, and nothing is saved over it: %2</translation>
    </message>
    <message>
        <source>The result is not saved: %1</source>
        <translation>The result is not saved: %1</translation>
    </message>
    <message>
        <source>The machine&apos;s profile</source>
        <translation>The machine&apos;s profile</translation>
    </message>
    <message>
        <source>StepCom profiles (*.json)</source>
        <translation>StepCom profiles (*.json)</translation>
    </message>
    <message>
        <source>No profile chosen: the progress is kept in %1. Choose the machine&apos;s profile to keep it beside it.</source>
        <translation>No profile chosen: the progress is kept in %1. Choose the machine&apos;s profile to keep it beside it.</translation>
    </message>
    <message>
        <source>Profile %1 — the progress is kept in %2</source>
        <translation>Profile %1 — the progress is kept in %2</translation>
    </message>
    <message>
        <source>Choose &amp;profile…</source>
        <translation>Choose &amp;profile…</translation>
    </message>
</context>
<context>
    <name>stepcom::ChecklistProofStep</name>
    <message>
        <source>auto</source>
        <translation>auto</translation>
    </message>
    <message>
        <source>After the moves out: %1 mm</source>
        <translation>After the moves out: %1 mm</translation>
    </message>
    <message>
        <source>After the moves back: %1 mm</source>
        <translation>After the moves back: %1 mm</translation>
    </message>
    <message>
        <source>Run it? The axis will move.</source>
        <translation>Run it? The axis will move.</translation>
    </message>
    <message>
        <source>Write the recommended acceleration %1…</source>
        <translation>Write the recommended acceleration %1…</translation>
    </message>
    <message>
        <source>Write the recommended speed %1 rpm…</source>
        <translation>Write the recommended speed %1 rpm…</translation>
    </message>
    <message>
        <source>The recommendation was not written.</source>
        <translation>The recommendation was not written.</translation>
    </message>
    <message>
        <source>The recommendation is written and verified. Run the lost-step test again to prove it.</source>
        <translation>The recommendation is written and verified. Run the lost-step test again to prove it.</translation>
    </message>
    <message>
        <source>C&amp;ycles:</source>
        <translation>C&amp;ycles:</translation>
    </message>
    <message>
        <source>&amp;Distance of each move:</source>
        <translation>&amp;Distance of each move:</translation>
    </message>
    <message>
        <source>Margin: &amp;from, to, step:</source>
        <translation>Margin: &amp;from, to, step:</translation>
    </message>
    <message>
        <source>Cycles</source>
        <translation>Cycles</translation>
    </message>
    <message>
        <source>Distance of each move</source>
        <translation>Distance of each move</translation>
    </message>
    <message>
        <source>Margin from</source>
        <translation>Margin from</translation>
    </message>
    <message>
        <source>Margin to</source>
        <translation>Margin to</translation>
    </message>
    <message>
        <source>Margin step</source>
        <translation>Margin step</translation>
    </message>
    <message>
        <source>Search the &amp;acceleration instead of the speed</source>
        <translation>Search the &amp;acceleration instead of the speed</translation>
    </message>
    <message>
        <source>Run the &amp;lost-step test</source>
        <translation>Run the &amp;lost-step test</translation>
    </message>
    <message>
        <source>Find the &amp;margin</source>
        <translation>Find the &amp;margin</translation>
    </message>
    <message>
        <source>&amp;Stop</source>
        <translation>&amp;Stop</translation>
    </message>
    <message>
        <source>Test progress</source>
        <translation>Test progress</translation>
    </message>
    <message>
        <source>The margin search: lost mm at each value tested</source>
        <translation>The margin search: lost mm at each value tested</translation>
    </message>
</context>
<context>
    <name>stepcom::ChecklistRunInStep</name>
    <message>
        <source>Open the Sequence page</source>
        <translation>Open the Sequence page</translation>
    </message>
</context>
<context>
    <name>stepcom::ChecklistStep</name>
    <message>
        <source>Not run</source>
        <translation>Not run</translation>
    </message>
    <message>
        <source>Passed</source>
        <translation>Passed</translation>
    </message>
    <message>
        <source>Failed</source>
        <translation>Failed</translation>
    </message>
    <message>
        <source>Skipped</source>
        <translation>Skipped</translation>
    </message>
    <message>
        <source>direction</source>
        <translation>direction</translation>
    </message>
    <message>
        <source>travel calibration</source>
        <translation>travel calibration</translation>
    </message>
    <message>
        <source>positive limit input</source>
        <translation>positive limit input</translation>
    </message>
    <message>
        <source>negative limit input</source>
        <translation>negative limit input</translation>
    </message>
    <message>
        <source>home input</source>
        <translation>home input</translation>
    </message>
    <message>
        <source>homing</source>
        <translation>homing</translation>
    </message>
    <message>
        <source>Machine: homing order</source>
        <translation>Machine: homing order</translation>
    </message>
    <message>
        <source>Machine: interpolation test</source>
        <translation>Machine: interpolation test</translation>
    </message>
    <message>
        <source>Machine: save to flash and read back</source>
        <translation>Machine: save to flash and read back</translation>
    </message>
    <message>
        <source>Motor %1: %2</source>
        <translation>Motor %1: %2</translation>
    </message>
    <message>
        <source>Move motor %1 a small step forward. Did the axis move toward + ? No offers to flip its direction register.</source>
        <translation>Move motor %1 a small step forward. Did the axis move toward + ? No offers to flip its direction register.</translation>
    </message>
    <message>
        <source>Move motor %1 by a distance you choose, measure what the axis really moved and type it in: StepCom proposes the corrected pitch (pitch × measured ÷ commanded).</source>
        <translation>Move motor %1 by a distance you choose, measure what the axis really moved and type it in: StepCom proposes the corrected pitch (pitch × measured ÷ commanded).</translation>
    </message>
    <message>
        <source>Press the positive limit switch of motor %1 by hand: StepCom watches the inputs and compares the one that changed with the configuration.</source>
        <translation>Press the positive limit switch of motor %1 by hand: StepCom watches the inputs and compares the one that changed with the configuration.</translation>
    </message>
    <message>
        <source>Press the negative limit switch of motor %1 by hand: StepCom watches the inputs and compares the one that changed with the configuration.</source>
        <translation>Press the negative limit switch of motor %1 by hand: StepCom watches the inputs and compares the one that changed with the configuration.</translation>
    </message>
    <message>
        <source>Press the home switch of motor %1 by hand (often the negative limit&apos;s switch): StepCom compares the input that changed with the configuration.</source>
        <translation>Press the home switch of motor %1 by hand (often the negative limit&apos;s switch): StepCom compares the input that changed with the configuration.</translation>
    </message>
    <message>
        <source>Home motor %1 and check that it ended on its home switch, referenced.</source>
        <translation>Home motor %1 and check that it ended on its home switch, referenced.</translation>
    </message>
    <message>
        <source>Home the machine in the configured order and check that every axis in the order ended referenced.</source>
        <translation>Home the machine in the configured order and check that every axis in the order ended referenced.</translation>
    </message>
    <message>
        <source>Run the configured arc or line and check that the axes ended at its end point.</source>
        <translation>Run the configured arc or line and check that the axes ended at its end point.</translation>
    </message>
    <message>
        <source>Save the parameters to flash, read them back and compare them with what was written.</source>
        <translation>Save the parameters to flash, read them back and compare them with what was written.</translation>
    </message>
    <message>
        <source>Commanded distance</source>
        <translation>Commanded distance</translation>
    </message>
    <message>
        <source>Measured distance</source>
        <translation>Measured distance</translation>
    </message>
    <message>
        <source>Pitch before</source>
        <translation>Pitch before</translation>
    </message>
    <message>
        <source>Pitch after</source>
        <translation>Pitch after</translation>
    </message>
    <message>
        <source>Moved toward +</source>
        <translation>Moved toward +</translation>
    </message>
    <message>
        <source>Direction before</source>
        <translation>Direction before</translation>
    </message>
    <message>
        <source>Direction after</source>
        <translation>Direction after</translation>
    </message>
    <message>
        <source>Input configured</source>
        <translation>Input configured</translation>
    </message>
    <message>
        <source>Input that answered</source>
        <translation>Input that answered</translation>
    </message>
    <message>
        <source>Fix written</source>
        <translation>Fix written</translation>
    </message>
    <message>
        <source>End position</source>
        <translation>End position</translation>
    </message>
    <message>
        <source>Expected end</source>
        <translation>Expected end</translation>
    </message>
    <message>
        <source>Homing order</source>
        <translation>Homing order</translation>
    </message>
    <message>
        <source>Read back</source>
        <translation>Read back</translation>
    </message>
    <message>
        <source>keeps its steps</source>
        <translation>keeps its steps</translation>
    </message>
    <message>
        <source>backlash</source>
        <translation>backlash</translation>
    </message>
    <message>
        <source>Prove that motor %1 keeps its steps at its own speed and acceleration: the count against the home switch before and after moves out fast and back slowly, and the other way. Then find the margin: the test at each speed on the way up, to the first loss.</source>
        <translation>Prove that motor %1 keeps its steps at its own speed and acceleration: the count against the home switch before and after moves out fast and back slowly, and the other way. Then find the margin: the test at each speed on the way up, to the first loss.</translation>
    </message>
    <message>
        <source>Put a dial gauge on motor %1&apos;s carriage. StepCom approaches a point from one side, then moves on and back; type what the gauge shows after each move.</source>
        <translation>Put a dial gauge on motor %1&apos;s carriage. StepCom approaches a point from one side, then moves on and back; type what the gauge shows after each move.</translation>
    </message>
    <message>
        <source>Verdict</source>
        <translation>Verdict</translation>
    </message>
    <message>
        <source>Tested at speed</source>
        <translation>Tested at speed</translation>
    </message>
    <message>
        <source>Tested at acceleration</source>
        <translation>Tested at acceleration</translation>
    </message>
    <message>
        <source>Cycles</source>
        <translation>Cycles</translation>
    </message>
    <message>
        <source>Distance of each move</source>
        <translation>Distance of each move</translation>
    </message>
    <message>
        <source>Lost after the moves out</source>
        <translation>Lost after the moves out</translation>
    </message>
    <message>
        <source>Lost after the moves back</source>
        <translation>Lost after the moves back</translation>
    </message>
    <message>
        <source>Switch repeatability</source>
        <translation>Switch repeatability</translation>
    </message>
    <message>
        <source>Highest speed kept</source>
        <translation>Highest speed kept</translation>
    </message>
    <message>
        <source>First speed lost</source>
        <translation>First speed lost</translation>
    </message>
    <message>
        <source>Recommended speed</source>
        <translation>Recommended speed</translation>
    </message>
    <message>
        <source>Highest acceleration kept</source>
        <translation>Highest acceleration kept</translation>
    </message>
    <message>
        <source>First acceleration lost</source>
        <translation>First acceleration lost</translation>
    </message>
    <message>
        <source>Recommended acceleration</source>
        <translation>Recommended acceleration</translation>
    </message>
    <message>
        <source>Backlash</source>
        <translation>Backlash</translation>
    </message>
    <message>
        <source>Spread</source>
        <translation>Spread</translation>
    </message>
    <message>
        <source>Gauge readings</source>
        <translation>Gauge readings</translation>
    </message>
    <message>
        <source>Taken on</source>
        <translation>Taken on</translation>
    </message>
    <message>
        <source>Machine: run-in of its cycle</source>
        <translation>Machine: run-in of its cycle</translation>
    </message>
    <message>
        <source>Run the machine&apos;s cycle on the Sequence page for a number of cycles, with the lost-step check at the end. The run-in&apos;s result is recorded here: cycles, cycle time and whether every axis kept its steps.</source>
        <translation>Run the machine&apos;s cycle on the Sequence page for a number of cycles, with the lost-step check at the end. The run-in&apos;s result is recorded here: cycles, cycle time and whether every axis kept its steps.</translation>
    </message>
    <message>
        <source>Sequence</source>
        <translation>Sequence</translation>
    </message>
    <message>
        <source>Outcome</source>
        <translation>Outcome</translation>
    </message>
    <message>
        <source>Cycles done</source>
        <translation>Cycles done</translation>
    </message>
    <message>
        <source>Shortest cycle</source>
        <translation>Shortest cycle</translation>
    </message>
    <message>
        <source>Median cycle</source>
        <translation>Median cycle</translation>
    </message>
    <message>
        <source>Longest cycle</source>
        <translation>Longest cycle</translation>
    </message>
    <message>
        <source>Lost-step check</source>
        <translation>Lost-step check</translation>
    </message>
</context>
<context>
    <name>stepcom::ChecklistStepWidget</name>
    <message>
        <source>Skipped.</source>
        <translation>Skipped.</translation>
    </message>
    <message>
        <source>Not connected: nothing was written.</source>
        <translation>Not connected: nothing was written.</translation>
    </message>
    <message>
        <source>&amp;Note:</source>
        <translation>&amp;Note:</translation>
    </message>
    <message>
        <source>S&amp;kip this step</source>
        <translation>S&amp;kip this step</translation>
    </message>
</context>
<context>
    <name>stepcom::CommissioningReport</name>
    <message>
        <source>Controller</source>
        <translation>Controller</translation>
    </message>
    <message>
        <source>Device id</source>
        <translation>Device id</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>Link</translation>
    </message>
    <message>
        <source>Baud rate (register)</source>
        <translation>Baud rate (register)</translation>
    </message>
    <message>
        <source>Register map</source>
        <translation>Register map</translation>
    </message>
    <message>
        <source>round trips: %1</source>
        <translation>round trips: %1</translation>
    </message>
    <message>
        <source>System mode</source>
        <translation>System mode</translation>
    </message>
    <message>
        <source>Homing order</source>
        <translation>Homing order</translation>
    </message>
    <message>
        <source>first: %1, then: %2</source>
        <translation>first: %1, then: %2</translation>
    </message>
    <message>
        <source>Date</source>
        <translation>Date</translation>
    </message>
    <message>
        <source>StepCom version</source>
        <translation>StepCom version</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parameters</translation>
    </message>
    <message>
        <source>Motor %1</source>
        <translation>Motor %1</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Value</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Unit</translation>
    </message>
    <message>
        <source>Key</source>
        <translation>Key</translation>
    </message>
    <message>
        <source>Register</source>
        <translation>Register</translation>
    </message>
    <message>
        <source>Input wiring</source>
        <translation>Input wiring</translation>
    </message>
    <message>
        <source>Motor</source>
        <translation>Motor</translation>
    </message>
    <message>
        <source>Positive limit</source>
        <translation>Positive limit</translation>
    </message>
    <message>
        <source>Negative limit</source>
        <translation>Negative limit</translation>
    </message>
    <message>
        <source>Home input</source>
        <translation>Home input</translation>
    </message>
    <message>
        <source>No suspicious wiring found.</source>
        <translation>No suspicious wiring found.</translation>
    </message>
    <message>
        <source>Arc and line interpolation</source>
        <translation>Arc and line interpolation</translation>
    </message>
    <message>
        <source>Arc</source>
        <translation>Arc</translation>
    </message>
    <message>
        <source>Arc mode</source>
        <translation>Arc mode</translation>
    </message>
    <message>
        <source>Arc start</source>
        <translation>Arc start</translation>
    </message>
    <message>
        <source>Arc end</source>
        <translation>Arc end</translation>
    </message>
    <message>
        <source>Arc centre</source>
        <translation>Arc centre</translation>
    </message>
    <message>
        <source>Arc middle point</source>
        <translation>Arc middle point</translation>
    </message>
    <message>
        <source>Arc direction</source>
        <translation>Arc direction</translation>
    </message>
    <message>
        <source>Arc speed</source>
        <translation>Arc speed</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>Line</translation>
    </message>
    <message>
        <source>Line start</source>
        <translation>Line start</translation>
    </message>
    <message>
        <source>Line end</source>
        <translation>Line end</translation>
    </message>
    <message>
        <source>Line speed</source>
        <translation>Line speed</translation>
    </message>
    <message>
        <source>The arc cannot be drawn: %1</source>
        <translation>The arc cannot be drawn: %1</translation>
    </message>
    <message>
        <source>XY picture of the arc and the line</source>
        <translation>XY picture of the arc and the line</translation>
    </message>
    <message>
        <source>Commissioning report</source>
        <translation>Commissioning report</translation>
    </message>
    <message>
        <source>Notes</source>
        <translation>Notes</translation>
    </message>
    <message>
        <source>Controller (as the profile records it)</source>
        <translation>Controller (as the profile records it)</translation>
    </message>
    <message>
        <source>none: made from a file, not read from a controller</source>
        <translation>none: made from a file, not read from a controller</translation>
    </message>
    <message>
        <source>Baud rate</source>
        <translation>Baud rate</translation>
    </message>
    <message>
        <source>the profile was made with %1</source>
        <translation>the profile was made with %1</translation>
    </message>
    <message>
        <source>Profile file</source>
        <translation>Profile file</translation>
    </message>
    <message>
        <source>Profile saved</source>
        <translation>Profile saved</translation>
    </message>
    <message>
        <source>%1 by StepCom %2</source>
        <translation>%1 by StepCom %2</translation>
    </message>
    <message>
        <source>Report date</source>
        <translation>Report date</translation>
    </message>
    <message>
        <source>What of the profile this register map cannot show</source>
        <translation>What of the profile this register map cannot show</translation>
    </message>
    <message>
        <source>Commissioning report (from a profile file)</source>
        <translation>Commissioning report (from a profile file)</translation>
    </message>
    <message>
        <source>Made from the profile file %1, not read from a controller: these are the values the file holds; a controller may hold others.</source>
        <translation>Made from the profile file %1, not read from a controller: these are the values the file holds; a controller may hold others.</translation>
    </message>
    <message>
        <source>Settings fingerprint</source>
        <translation>Settings fingerprint</translation>
    </message>
    <message>
        <source>Values read</source>
        <translation>Values read</translation>
    </message>
    <message>
        <source>Flash</source>
        <translation>Flash</translation>
    </message>
    <message>
        <source>unknown: this program did not follow the writes</source>
        <translation>unknown: this program did not follow the writes</translation>
    </message>
    <message>
        <source>saved: nothing written since connecting or since the last save to flash</source>
        <translation>saved: nothing written since connecting or since the last save to flash</translation>
    </message>
    <message>
        <source>NOT saved: values were written since the last save to flash and are lost at power-off</source>
        <translation>NOT saved: values were written since the last save to flash and are lost at power-off</translation>
    </message>
    <message>
        <source>not supported by this controller</source>
        <translation>not supported by this controller</translation>
    </message>
    <message>
        <source>Not supported by this controller (it refuses to read them, a firmware variant): %1</source>
        <translation>Not supported by this controller (it refuses to read them, a firmware variant): %1</translation>
    </message>
    <message>
        <source>Link, as measured</source>
        <translation>Link, as measured</translation>
    </message>
    <message>
        <source>StepCom&apos;s built-in simulator -- not a machine</source>
        <translation>StepCom&apos;s built-in simulator -- not a machine</translation>
    </message>
    <message>
        <source>%1 -- simulator, not a machine</source>
        <translation>%1 -- simulator, not a machine</translation>
    </message>
    <message>
        <source>SIMULATOR -- NOT A MACHINE: these values were read from StepCom&apos;s built-in simulator. This sheet certifies no machine.</source>
        <translation>SIMULATOR -- NOT A MACHINE: these values were read from StepCom&apos;s built-in simulator. This sheet certifies no machine.</translation>
    </message>
</context>
<context>
    <name>stepcom::ConnectionPage</name>
    <message>
        <source>Disconnected.</source>
        <translation>Disconnected.</translation>
    </message>
    <message>
        <source>Connection lost: %1</source>
        <translation>Connection lost: %1</translation>
    </message>
    <message>
        <source>Connection</source>
        <translation>Connection</translation>
    </message>
    <message>
        <source>Connect through</source>
        <translation>Connect through</translation>
    </message>
    <message>
        <source>&amp;Serial (RTU)</source>
        <translation>&amp;Serial (RTU)</translation>
    </message>
    <message>
        <source>Modbus RTU over RS-485 or RS-232, e.g. a USB adapter</source>
        <translation>Modbus RTU over RS-485 or RS-232, e.g. a USB adapter</translation>
    </message>
    <message>
        <source>Modbus &amp;TCP</source>
        <translation>Modbus &amp;TCP</translation>
    </message>
    <message>
        <source>Modbus TCP, e.g. through an Ethernet-to-RS-485 gateway</source>
        <translation>Modbus TCP, e.g. through an Ethernet-to-RS-485 gateway</translation>
    </message>
    <message>
        <source>Built-in si&amp;mulator</source>
        <translation>Built-in si&amp;mulator</translation>
    </message>
    <message>
        <source>A simulated controller inside StepCom: try every page without a machine</source>
        <translation>A simulated controller inside StepCom: try every page without a machine</translation>
    </message>
    <message>
        <source>Serial port</source>
        <translation>Serial port</translation>
    </message>
    <message>
        <source>&amp;Port:</source>
        <translation>&amp;Port:</translation>
    </message>
    <message>
        <source>The serial port, e.g. /dev/ttyUSB0 or COM3. Any path can be typed: pseudo-terminals are not listed.</source>
        <translation>The serial port, e.g. /dev/ttyUSB0 or COM3. Any path can be typed: pseudo-terminals are not listed.</translation>
    </message>
    <message>
        <source>/dev/ttyUSB0 or a path</source>
        <translation>/dev/ttyUSB0 or a path</translation>
    </message>
    <message>
        <source>Re&amp;fresh</source>
        <translation>Re&amp;fresh</translation>
    </message>
    <message>
        <source>List the serial ports again (after plugging in an adapter)</source>
        <translation>List the serial ports again (after plugging in an adapter)</translation>
    </message>
    <message>
        <source>&amp;Baud rate:</source>
        <translation>&amp;Baud rate:</translation>
    </message>
    <message>
        <source>The controller&apos;s baud rate (register 40213); factory setting 9600</source>
        <translation>The controller&apos;s baud rate (register 40213); factory setting 9600</translation>
    </message>
    <message>
        <source>Parit&amp;y:</source>
        <translation>Parit&amp;y:</translation>
    </message>
    <message>
        <source>The controller uses no parity (8N1) unless set otherwise</source>
        <translation>The controller uses no parity (8N1) unless set otherwise</translation>
    </message>
    <message>
        <source>None</source>
        <translation>None</translation>
    </message>
    <message>
        <source>Even</source>
        <translation>Even</translation>
    </message>
    <message>
        <source>Odd</source>
        <translation>Odd</translation>
    </message>
    <message>
        <source>St&amp;op bits:</source>
        <translation>St&amp;op bits:</translation>
    </message>
    <message>
        <source>The controller uses 1 stop bit</source>
        <translation>The controller uses 1 stop bit</translation>
    </message>
    <message>
        <source>Modbus TCP</source>
        <translation>Modbus TCP</translation>
    </message>
    <message>
        <source>&amp;Host:</source>
        <translation>&amp;Host:</translation>
    </message>
    <message>
        <source>Host name or IP address of the gateway or controller</source>
        <translation>Host name or IP address of the gateway or controller</translation>
    </message>
    <message>
        <source>192.168.0.7</source>
        <translation>192.168.0.7</translation>
    </message>
    <message>
        <source>TCP p&amp;ort:</source>
        <translation>TCP p&amp;ort:</translation>
    </message>
    <message>
        <source>TCP port of the Modbus server; 502 is the standard</source>
        <translation>TCP port of the Modbus server; 502 is the standard</translation>
    </message>
    <message>
        <source>Controller</source>
        <translation>Controller</translation>
    </message>
    <message>
        <source>Device &amp;id:</source>
        <translation>Device &amp;id:</translation>
    </message>
    <message>
        <source>The controller&apos;s Modbus address (register 40212); factory setting 1. Use Scan bus when it is not known.</source>
        <translation>The controller&apos;s Modbus address (register 40212); factory setting 1. Use Scan bus when it is not known.</translation>
    </message>
    <message>
        <source>Tim&amp;eout:</source>
        <translation>Tim&amp;eout:</translation>
    </message>
    <message>
        <source>How long to wait for each answer before trying again</source>
        <translation>How long to wait for each answer before trying again</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>&amp;Retries:</source>
        <translation>&amp;Retries:</translation>
    </message>
    <message>
        <source>How often an unanswered request is sent again</source>
        <translation>How often an unanswered request is sent again</translation>
    </message>
    <message>
        <source>Built-in simulator</source>
        <translation>Built-in simulator</translation>
    </message>
    <message>
        <source>A simulated controller runs inside StepCom and answers like the real one: every page can be tried without a machine. Nothing reaches real hardware.</source>
        <translation>A simulated controller runs inside StepCom and answers like the real one: every page can be tried without a machine. Nothing reaches real hardware.</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>Link</translation>
    </message>
    <message>
        <source>&amp;Connect</source>
        <translation>&amp;Connect</translation>
    </message>
    <message>
        <source>Connect and read every parameter (nothing is written)</source>
        <translation>Connect and read every parameter (nothing is written)</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>&amp;Disconnect</translation>
    </message>
    <message>
        <source>Close the port; edits that were not written stay</source>
        <translation>Close the port; edits that were not written stay</translation>
    </message>
    <message>
        <source>Sc&amp;an bus…</source>
        <translation>Sc&amp;an bus…</translation>
    </message>
    <message>
        <source>Find controllers whose device id or baud rate is not known</source>
        <translation>Find controllers whose device id or baud rate is not known</translation>
    </message>
    <message>
        <source>Cannot connect: %1.</source>
        <translation>Cannot connect: %1.</translation>
    </message>
    <message>
        <source>Could not connect to %1: %2</source>
        <translation>Could not connect to %1: %2</translation>
    </message>
    <message>
        <source>the built-in simulator</source>
        <translation>the built-in simulator</translation>
    </message>
    <message>
        <source>Connected to the built-in simulator (%1).</source>
        <translation>Connected to the built-in simulator (%1).</translation>
    </message>
    <message>
        <source>Connected to %1.</source>
        <translation>Connected to %1.</translation>
    </message>
    <message>
        <source>Connecting to %1…</source>
        <translation>Connecting to %1…</translation>
    </message>
    <message>
        <source>Not connected.</source>
        <translation>Not connected.</translation>
    </message>
    <message>
        <source>%1 is open, but the controller does not answer.</source>
        <translation>%1 is open, but the controller does not answer.</translation>
    </message>
    <message>
        <source>%1 is open; waiting for the controller to answer…</source>
        <translation>%1 is open; waiting for the controller to answer…</translation>
    </message>
    <message>
        <source>Serial port plugged in: %1</source>
        <translation>Serial port plugged in: %1</translation>
    </message>
    <message>
        <source>Network</source>
        <translation>Network</translation>
    </message>
    <message>
        <source>&amp;Protocol:</source>
        <translation>&amp;Protocol:</translation>
    </message>
    <message>
        <source>Modbus TCP for a Modbus gateway; a transparent RS-485/Ethernet converter passes Modbus RTU frames (with CRC) over TCP, the default mode of most cheap converters</source>
        <translation>Modbus TCP for a Modbus gateway; a transparent RS-485/Ethernet converter passes Modbus RTU frames (with CRC) over TCP, the default mode of most cheap converters</translation>
    </message>
    <message>
        <source>RS-485/Ethernet converter (transparent)</source>
        <translation>RS-485/Ethernet converter (transparent)</translation>
    </message>
    <message>
        <source>Line: %1</source>
        <translation>Line: %1</translation>
    </message>
    <message>
        <source>A controller simulated inside StepCom: nothing reaches real hardware.</source>
        <translation>A controller simulated inside StepCom: nothing reaches real hardware.</translation>
    </message>
</context>
<context>
    <name>stepcom::CtlBusMonitor</name>
    <message>
        <source>link lost: %1</source>
        <translation>link lost: %1</translation>
    </message>
    <message>
        <source>id %1</source>
        <translation>id %1</translation>
    </message>
    <message>
        <source>id %1: %2</source>
        <translation>id %1: %2</translation>
    </message>
</context>
<context>
    <name>stepcom::CtlLinkAdvice</name>
    <message>
        <source>not saved to flash: the built-in simulator starts its next run with the id and baud it saved (add --save-to-flash to keep them)</source>
        <translation>not saved to flash: the built-in simulator starts its next run with the id and baud it saved (add --save-to-flash to keep them)</translation>
    </message>
    <message>
        <source>not saved to flash: after the next power-off the controller answers at the id and baud it saved before (add --save-to-flash to keep them)</source>
        <translation>not saved to flash: after the next power-off the controller answers at the id and baud it saved before (add --save-to-flash to keep them)</translation>
    </message>
    <message>
        <source>the controller now speaks %1 baud on its RS-485 side: set the converter&apos;s (gateway&apos;s) serial side to %1 baud too, or it no longer reaches the controller</source>
        <translation>the controller now speaks %1 baud on its RS-485 side: set the converter&apos;s (gateway&apos;s) serial side to %1 baud too, or it no longer reaches the controller</translation>
    </message>
    <message>
        <source>next commands: stepcomctl %1 ...</source>
        <translation>next commands: stepcomctl %1 ...</translation>
    </message>
</context>
<context>
    <name>stepcom::CtlListen</name>
    <message>
        <source>stepcomctl: the port %1 was lost: %2</source>
        <translation>stepcomctl: the port %1 was lost: %2</translation>
    </message>
    <message>
        <source>stepcomctl: cannot open %1 to listen: %2</source>
        <translation>stepcomctl: cannot open %1 to listen: %2</translation>
    </message>
    <message>
        <source>listening on %1 at %2 baud; nothing is sent (Ctrl-C ends)</source>
        <translation>listening on %1 at %2 baud; nothing is sent (Ctrl-C ends)</translation>
    </message>
    <message>
        <source>adapter: %1</source>
        <translation>adapter: %1</translation>
    </message>
    <message>
        <source>heard %1 frames (%2 bytes): %3 pairs, %4 unanswered, %5 exceptions, %6 CRC errors (frames skipped), %7 stray bytes, %8 answers without their request</source>
        <translation>heard %1 frames (%2 bytes): %3 pairs, %4 unanswered, %5 exceptions, %6 CRC errors (frames skipped), %7 stray bytes, %8 answers without their request</translation>
    </message>
    <message>
        <source>id %1: %2 requests, %3 answered in %4-%5 ms (%6 ms on average), %7 unanswered</source>
        <translation>id %1: %2 requests, %3 answered in %4-%5 ms (%6 ms on average), %7 unanswered</translation>
    </message>
    <message>
        <source>id %1: %2 requests, none answered</source>
        <translation>id %1: %2 requests, none answered</translation>
    </message>
</context>
<context>
    <name>stepcom::CtlMonitor</name>
    <message>
        <source>no sample was read: every poll failed (see the errors above)</source>
        <translation>no sample was read: every poll failed (see the errors above)</translation>
    </message>
    <message>
        <source>link lost: %1; trying again on its own (Ctrl-C ends)</source>
        <translation>link lost: %1; trying again on its own (Ctrl-C ends)</translation>
    </message>
    <message numerus="yes">
        <source>link back at %1 after %n attempt(s)</source>
        <translation>
            <numerusform>link back at %1 after %n attempt</numerusform>
            <numerusform>link back at %1 after %n attempts</numerusform>
        </translation>
    </message>
    <message>
        <source>; not saved to flash, lost: %1</source>
        <translation>; not saved to flash, lost: %1</translation>
    </message>
    <message>
        <source>controller %1 restarted (power off?): positions and references lost%2%3</source>
        <translation>controller %1 restarted (power off?): positions and references lost%2%3</translation>
    </message>
    <message>
        <source>; seen: %1</source>
        <translation>; seen: %1</translation>
    </message>
    <message>
        <source>controller %1 may have restarted (power off?): it did not answer for %2 s and every axis reads 0 (%3); whether a motion ended there cannot be told: the references are not known, home again</source>
        <translation>controller %1 may have restarted (power off?): it did not answer for %2 s and every axis reads 0 (%3); whether a motion ended there cannot be told: the references are not known, home again</translation>
    </message>
</context>
<context>
    <name>stepcom::CtlMotionWait</name>
    <message>
        <source>%1 would not move anything here (nothing in the homing order, or every motor runs): nothing to wait for</source>
        <translation>%1 would not move anything here (nothing in the homing order, or every motor runs): nothing to wait for</translation>
    </message>
    <message>
        <source>%1: sent, waiting for the motion to end</source>
        <translation>%1: sent, waiting for the motion to end</translation>
    </message>
</context>
<context>
    <name>stepcom::CtlOptions</name>
    <message>
        <source>Serial port of the controller (e.g. /dev/ttyUSB0, COM3).</source>
        <translation>Serial port of the controller (e.g. /dev/ttyUSB0, COM3).</translation>
    </message>
    <message>
        <source>path</source>
        <translation>path</translation>
    </message>
    <message>
        <source>Modbus TCP gateway or simulator, HOST[:PORT] (port 502).</source>
        <translation>Modbus TCP gateway or simulator, HOST[:PORT] (port 502).</translation>
    </message>
    <message>
        <source>host:port</source>
        <translation>host:port</translation>
    </message>
    <message>
        <source>Baud rate: 4800, 9600, 19200 or 38400 (default 9600).</source>
        <translation>Baud rate: 4800, 9600, 19200 or 38400 (default 9600).</translation>
    </message>
    <message>
        <source>rate</source>
        <translation>rate</translation>
    </message>
    <message>
        <source>parity</source>
        <translation>parity</translation>
    </message>
    <message>
        <source>Stop bits: 1 or 2 (default 1).</source>
        <translation>Stop bits: 1 or 2 (default 1).</translation>
    </message>
    <message>
        <source>n</source>
        <translation>n</translation>
    </message>
    <message>
        <source>id</source>
        <translation>id</translation>
    </message>
    <message>
        <source>Answer timeout in ms (default 500).</source>
        <translation>Answer timeout in ms (default 500).</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <source>Retries after a timeout (default 2).</source>
        <translation>Retries after a timeout (default 2).</translation>
    </message>
    <message>
        <source>Register map file to use instead of the built-in one.</source>
        <translation>Register map file to use instead of the built-in one.</translation>
    </message>
    <message>
        <source>file</source>
        <translation>file</translation>
    </message>
    <message>
        <source>Show the Modbus traffic on standard error.</source>
        <translation>Show the Modbus traffic on standard error.</translation>
    </message>
    <message>
        <source>Do not ask: needed for commands that destroy settings.</source>
        <translation>Do not ask: needed for commands that destroy settings.</translation>
    </message>
    <message>
        <source>After writing, save the parameters to flash.</source>
        <translation>After writing, save the parameters to flash.</translation>
    </message>
    <message>
        <source>monitor: number of samples (default: until stopped).</source>
        <translation>monitor: number of samples (default: until stopped).</translation>
    </message>
    <message>
        <source>monitor: ms between samples (default: as fast as the link allows).</source>
        <translation>monitor: ms between samples (default: as fast as the link allows).</translation>
    </message>
    <message>
        <source>--tcp: &apos;%1&apos; is not HOST[:PORT]</source>
        <translation>--tcp: &apos;%1&apos; is not HOST[:PORT]</translation>
    </message>
    <message>
        <source>--baud: &apos;%1&apos; is not a number</source>
        <translation>--baud: &apos;%1&apos; is not a number</translation>
    </message>
    <message>
        <source>--parity: &apos;%1&apos; is not none, even or odd</source>
        <translation>--parity: &apos;%1&apos; is not none, even or odd</translation>
    </message>
    <message>
        <source>--stop-bits: &apos;%1&apos; is not 1 or 2</source>
        <translation>--stop-bits: &apos;%1&apos; is not 1 or 2</translation>
    </message>
    <message>
        <source>--timeout: &apos;%1&apos; is not a number</source>
        <translation>--timeout: &apos;%1&apos; is not a number</translation>
    </message>
    <message>
        <source>--retries: &apos;%1&apos; is not a number</source>
        <translation>--retries: &apos;%1&apos; is not a number</translation>
    </message>
    <message>
        <source>--count: &apos;%1&apos; is not a positive number</source>
        <translation>--count: &apos;%1&apos; is not a positive number</translation>
    </message>
    <message>
        <source>--interval: &apos;%1&apos; is not a number of ms</source>
        <translation>--interval: &apos;%1&apos; is not a number of ms</translation>
    </message>
    <message>
        <source>dump, apply: include the device id and baud (apply writes them only with this).</source>
        <translation>dump, apply: include the device id and baud (apply writes them only with this).</translation>
    </message>
    <message>
        <source>dump, report: name of the profile or the machine.</source>
        <translation>dump, report: name of the profile or the machine.</translation>
    </message>
    <message>
        <source>text</source>
        <translation>text</translation>
    </message>
    <message>
        <source>dump, report: notes to record.</source>
        <translation>dump, report: notes to record.</translation>
    </message>
    <message>
        <source>report: make the report from this profile file, not from a controller.</source>
        <translation>report: make the report from this profile file, not from a controller.</translation>
    </message>
    <message>
        <source>profile</source>
        <translation>profile</translation>
    </message>
    <message>
        <source>command: wait until a motion command ends and print how it ended (exit 0 only when done or referenced).</source>
        <translation>command: wait until a motion command ends and print how it ended (exit 0 only when done or referenced).</translation>
    </message>
    <message>
        <source>apply, command factory_reset/save_to_flash, write device.id/device.baud: do not save a backup of the controller&apos;s settings first.</source>
        <translation>apply, command factory_reset/save_to_flash, write device.id/device.baud: do not save a backup of the controller&apos;s settings first.</translation>
    </message>
    <message>
        <source>move: a step of this many axis units (+ or -).</source>
        <translation>move: a step of this many axis units (+ or -).</translation>
    </message>
    <message>
        <source>distance</source>
        <translation>distance</translation>
    </message>
    <message>
        <source>--id: %1</source>
        <translation>--id: %1</translation>
    </message>
    <message>
        <source>--to: &apos;%1&apos; is not a device id 1-255</source>
        <translation>--to: &apos;%1&apos; is not a device id 1-255</translation>
    </message>
    <message>
        <source>move: to this position (axis units); assign-id: the new device id 1-255.</source>
        <translation>move: to this position (axis units); assign-id: the new device id 1-255.</translation>
    </message>
    <message>
        <source>value</source>
        <translation>value</translation>
    </message>
    <message>
        <source>RS-485/Ethernet converter in transparent mode: Modbus RTU frames over TCP, HOST:PORT.</source>
        <translation>RS-485/Ethernet converter in transparent mode: Modbus RTU frames over TCP, HOST:PORT.</translation>
    </message>
    <message>
        <source>Extra silence after an answer before the next request, for converters that need it (default 0).</source>
        <translation>Extra silence after an answer before the next request, for converters that need it (default 0).</translation>
    </message>
    <message>
        <source>give only one of --port, --tcp, --rtu-tcp and --sim</source>
        <translation>give only one of --port, --tcp, --rtu-tcp and --sim</translation>
    </message>
    <message>
        <source>--rtu-tcp: &apos;%1&apos; is not HOST:PORT (converters have no standard port: see its settings page)</source>
        <translation>--rtu-tcp: &apos;%1&apos; is not HOST:PORT (converters have no standard port: see its settings page)</translation>
    </message>
    <message>
        <source>--answer-delay: &apos;%1&apos; is not a number of ms</source>
        <translation>--answer-delay: &apos;%1&apos; is not a number of ms</translation>
    </message>
    <message>
        <source>--turnaround: &apos;%1&apos; is not a number of ms</source>
        <translation>--turnaround: &apos;%1&apos; is not a number of ms</translation>
    </message>
    <message>
        <source>--echo: Modbus TCP has no echo; it applies to --port and --rtu-tcp</source>
        <translation>--echo: Modbus TCP has no echo; it applies to --port and --rtu-tcp</translation>
    </message>
    <message>
        <source>Device id 1-255 (default 1); several (1,2,3 or 1-3) for read, monitor, diff, apply, dump, report and command: each in turn on the one line, output keyed by id (report: one document).</source>
        <translation>Device id 1-255 (default 1); several (1,2,3 or 1-3) for read, monitor, diff, apply, dump, report and command: each in turn on the one line, output keyed by id (report: one document).</translation>
    </message>
    <message>
        <source>Parity: none, even or odd (default none); scan: several, e.g. none,even,odd.</source>
        <translation>Parity: none, even or odd (default none); scan: several, e.g. none,even,odd.</translation>
    </message>
    <message>
        <source>scan: the baud rates to try, e.g. 9600,19200 (default all four, 9600 first); not over --tcp or --rtu-tcp, where the converter&apos;s line has its own.</source>
        <translation>scan: the baud rates to try, e.g. 9600,19200 (default all four, 9600 first); not over --tcp or --rtu-tcp, where the converter&apos;s line has its own.</translation>
    </message>
    <message>
        <source>list</source>
        <translation>list</translation>
    </message>
    <message>
        <source>scan: the device ids to try, e.g. 1-32 or 1,5,7 (default 1-247).</source>
        <translation>scan: the device ids to try, e.g. 1-32 or 1,5,7 (default 1-247).</translation>
    </message>
    <message>
        <source>range</source>
        <translation>range</translation>
    </message>
    <message>
        <source>scan: wait this long for each id&apos;s answer (default: fitted to the baud, 67 ms at 9600); more for controllers that answer slowly.</source>
        <translation>scan: wait this long for each id&apos;s answer (default: fitted to the baud, 67 ms at 9600); more for controllers that answer slowly.</translation>
    </message>
    <message>
        <source>--%1: over --tcp and --rtu-tcp the converter&apos;s serial line has its own baud and parity (set on the converter); the scan tries only ids there</source>
        <translation>--%1: over --tcp and --rtu-tcp the converter&apos;s serial line has its own baud and parity (set on the converter); the scan tries only ids there</translation>
    </message>
    <message>
        <source>--parity: &apos;%1&apos; is given twice</source>
        <translation>--parity: &apos;%1&apos; is given twice</translation>
    </message>
    <message>
        <source>--parity: give one parity; several are for scan</source>
        <translation>--parity: give one parity; several are for scan</translation>
    </message>
    <message>
        <source>--%1 is an option of scan</source>
        <translation>--%1 is an option of scan</translation>
    </message>
    <message>
        <source>--bauds: &apos;%1&apos; is not one of %2</source>
        <translation>--bauds: &apos;%1&apos; is not one of %2</translation>
    </message>
    <message>
        <source>--bauds: %1 is given twice</source>
        <translation>--bauds: %1 is given twice</translation>
    </message>
    <message>
        <source>--ids: %1</source>
        <translation>--ids: %1</translation>
    </message>
    <message>
        <source>--probe-timeout: &apos;%1&apos; is not a number of ms from 1 to 10000</source>
        <translation>--probe-timeout: &apos;%1&apos; is not a number of ms from 1 to 10000</translation>
    </message>
    <message>
        <source>The adapter echoes what it sends (half-duplex USB-RS485 adapters without echo suppression): skip the request&apos;s own bytes from the first request on (without it the echo is found by the first read and skipped from then on).</source>
        <translation>The adapter echoes what it sends (half-duplex USB-RS485 adapters without echo suppression): skip the request&apos;s own bytes from the first request on (without it the echo is found by the first read and skipped from then on).</translation>
    </message>
    <message>
        <source>How long the controller may take to answer: the least an adapted timeout allows (default 35, the manual&apos;s). Answers are judged by what they say, whenever they come.</source>
        <translation>How long the controller may take to answer: the least an adapted timeout allows (default 35, the manual&apos;s). Answers are judged by what they say, whenever they come.</translation>
    </message>
    <message>
        <source>Always wait --timeout for an answer, instead of fitting the timeout to the controller&apos;s measured answers (4x the median, at most --timeout).</source>
        <translation>Always wait --timeout for an answer, instead of fitting the timeout to the controller&apos;s measured answers (4x the median, at most --timeout).</translation>
    </message>
    <message>
        <source>Append the session log of this run (every frame, with its time) to this file; stepcomctl replay reads it.</source>
        <translation>Append the session log of this run (every frame, with its time) to this file; stepcomctl replay reads it.</translation>
    </message>
    <message>
        <source>replay: list what happened (time, device, what).</source>
        <translation>replay: list what happened (time, device, what).</translation>
    </message>
    <message>
        <source>replay: the state of every device at TIME: seconds from the log&apos;s start or a clock time hh:mm:ss[.mmm].</source>
        <translation>replay: the state of every device at TIME: seconds from the log&apos;s start or a clock time hh:mm:ss[.mmm].</translation>
    </message>
    <message>
        <source>time</source>
        <translation>time</translation>
    </message>
    <message>
        <source>replay: what changed from T1 to the time after it (--diff T1 T2).</source>
        <translation>replay: what changed from T1 to the time after it (--diff T1 T2).</translation>
    </message>
    <message>
        <source>T1</source>
        <translation>T1</translation>
    </message>
    <message>
        <source>replay of a support bundle: the log inside to replay (default: the newest).</source>
        <translation>replay of a support bundle: the log inside to replay (default: the newest).</translation>
    </message>
    <message>
        <source>name</source>
        <translation>name</translation>
    </message>
    <message>
        <source>bundle: the session logs of the last N days (default 7).</source>
        <translation>bundle: the session logs of the last N days (default 7).</translation>
    </message>
    <message>
        <source>bundle: the profile (and its checklist) to add.</source>
        <translation>bundle: the profile (and its checklist) to add.</translation>
    </message>
    <message>
        <source>--days: &apos;%1&apos; is not a number of days</source>
        <translation>--days: &apos;%1&apos; is not a number of days</translation>
    </message>
    <message>
        <source>Use the built-in simulated controller (it keeps what it saved to flash between runs).</source>
        <translation>Use the built-in simulated controller (it keeps what it saved to flash between runs).</translation>
    </message>
    <message>
        <source>Start the built-in simulator from the factory again (id 1, 9600 baud): forget what it saved to flash. Alone, or before a --sim command.</source>
        <translation>Start the built-in simulator from the factory again (id 1, 9600 baud): forget what it saved to flash. Alone, or before a --sim command.</translation>
    </message>
    <message>
        <source>--baud: &apos;%1&apos; is not 4800, 9600, 19200 or 38400</source>
        <translation>--baud: &apos;%1&apos; is not 4800, 9600, 19200 or 38400</translation>
    </message>
    <message>
        <source>listen: stop after N seconds (default: until Ctrl-C).</source>
        <translation>listen: stop after N seconds (default: until Ctrl-C).</translation>
    </message>
    <message>
        <source>Who switches an RS-485 adapter&apos;s direction: auto (the adapter itself, default), kernel (the driver&apos;s RS-485 mode, RTS on send) or rts (StepCom raises RTS for each request).</source>
        <translation>Who switches an RS-485 adapter&apos;s direction: auto (the adapter itself, default), kernel (the driver&apos;s RS-485 mode, RTS on send) or rts (StepCom raises RTS for each request).</translation>
    </message>
    <message>
        <source>mode</source>
        <translation>mode</translation>
    </message>
    <message>
        <source>--rs485 kernel: the delays before and after sending, in us (default 0,0).</source>
        <translation>--rs485 kernel: the delays before and after sending, in us (default 0,0).</translation>
    </message>
    <message>
        <source>before,after</source>
        <translation>before,after</translation>
    </message>
    <message>
        <source>--rs485: &apos;%1&apos; is not auto, kernel or rts</source>
        <translation>--rs485: &apos;%1&apos; is not auto, kernel or rts</translation>
    </message>
    <message>
        <source>--rs485-delays: &apos;%1&apos; is not BEFORE,AFTER in us (e.g. 0,500)</source>
        <translation>--rs485-delays: &apos;%1&apos; is not BEFORE,AFTER in us (e.g. 0,500)</translation>
    </message>
    <message>
        <source>--seconds: &apos;%1&apos; is not a positive number of seconds</source>
        <translation>--seconds: &apos;%1&apos; is not a positive number of seconds</translation>
    </message>
    <message>
        <source>Machine-readable JSON: one object, exit, result and errors, for every command and usage error (monitor, listen: its last line).</source>
        <translation>Machine-readable JSON: one object, exit, result and errors, for every command and usage error (monitor, listen: its last line).</translation>
    </message>
    <message>
        <source>no command given (%1)</source>
        <translation>no command given (%1)</translation>
    </message>
    <message>
        <source>--cycles: &apos;%1&apos; is not a positive number</source>
        <translation>--cycles: &apos;%1&apos; is not a positive number</translation>
    </message>
    <message>
        <source>run: how many times the whole step list runs (default 1); lost-steps, backlash: back-and-forth moves (default 3); margin: at each value (default 2).</source>
        <translation>run: how many times the whole step list runs (default 1); lost-steps, backlash: back-and-forth moves (default 3); margin: at each value (default 2).</translation>
    </message>
    <message>
        <source>lost-steps, margin: each move of the test (default 10 axis units); backlash: each move (default 1).</source>
        <translation>lost-steps, margin: each move of the test (default 10 axis units); backlash: each move (default 1).</translation>
    </message>
    <message>
        <source>d</source>
        <translation>d</translation>
    </message>
    <message>
        <source>margin: the step between the values tested.</source>
        <translation>margin: the step between the values tested.</translation>
    </message>
    <message>
        <source>margin: search the acceleration register at the motor&apos;s own speed.</source>
        <translation>margin: search the acceleration register at the motor&apos;s own speed.</translation>
    </message>
    <message>
        <source>margin: write the recommended value, reviewed as write reviews it.</source>
        <translation>margin: write the recommended value, reviewed as write reviews it.</translation>
    </message>
    <message>
        <source>run: after the cycles, the lost-step test on every axis the sequence moved.</source>
        <translation>run: after the cycles, the lost-step test on every axis the sequence moved.</translation>
    </message>
</context>
<context>
    <name>stepcom::CtlRunner</name>
    <message>
        <source>done</source>
        <translation>done</translation>
    </message>
    <message>
        <source>no controller given: use --port PATH, --tcp HOST[:PORT] or --sim</source>
        <translation>no controller given: use --port PATH, --tcp HOST[:PORT] or --sim</translation>
    </message>
    <message>
        <source>cannot connect to %1: %2</source>
        <translation>cannot connect to %1: %2</translation>
    </message>
    <message>
        <source>cannot start the built-in simulator: %1</source>
        <translation>cannot start the built-in simulator: %1</translation>
    </message>
    <message>
        <source>unknown parameter &apos;%1&apos; (see: stepcomctl params)</source>
        <translation>unknown parameter &apos;%1&apos; (see: stepcomctl params)</translation>
    </message>
    <message>
        <source>%1 is a command and cannot be read</source>
        <translation>%1 is a command and cannot be read</translation>
    </message>
    <message>
        <source>write needs KEY=VALUE arguments</source>
        <translation>write needs KEY=VALUE arguments</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not KEY=VALUE</source>
        <translation>&apos;%1&apos; is not KEY=VALUE</translation>
    </message>
    <message>
        <source>%1 is a command: use &apos;stepcomctl command %1&apos;</source>
        <translation>%1 is a command: use &apos;stepcomctl command %1&apos;</translation>
    </message>
    <message>
        <source>%1 is read-only</source>
        <translation>%1 is read-only</translation>
    </message>
    <message>
        <source>nothing was written</source>
        <translation>nothing was written</translation>
    </message>
    <message>
        <source>(written, verified)</source>
        <translation>(written, verified)</translation>
    </message>
    <message>
        <source>not written: %1</source>
        <translation>not written: %1</translation>
    </message>
    <message>
        <source>this map has no save_to_flash command</source>
        <translation>this map has no save_to_flash command</translation>
    </message>
    <message>
        <source>saved to flash</source>
        <translation>saved to flash</translation>
    </message>
    <message>
        <source>command needs exactly one command name (see: stepcomctl params)</source>
        <translation>command needs exactly one command name (see: stepcomctl params)</translation>
    </message>
    <message>
        <source>%1 is a parameter, not a command: use read or write</source>
        <translation>%1 is a parameter, not a command: use read or write</translation>
    </message>
    <message>
        <source>unknown command &apos;%1&apos; (see: stepcomctl params)</source>
        <translation>unknown command &apos;%1&apos; (see: stepcomctl params)</translation>
    </message>
    <message>
        <source>%1 destroys settings (%2); add --yes if you mean it</source>
        <translation>%1 destroys settings (%2); add --yes if you mean it</translation>
    </message>
    <message>
        <source>%1: done</source>
        <translation>%1: done</translation>
    </message>
    <message>
        <source>monitor takes no arguments, only --count and --interval</source>
        <translation>monitor takes no arguments, only --count and --interval</translation>
    </message>
    <message>
        <source>%1 needs exactly one profile file</source>
        <translation>%1 needs exactly one profile file</translation>
    </message>
    <message>
        <source>dump needs exactly one file to write the profile to</source>
        <translation>dump needs exactly one file to write the profile to</translation>
    </message>
    <message>
        <source>nothing was saved: the controller could not be read completely</source>
        <translation>nothing was saved: the controller could not be read completely</translation>
    </message>
    <message numerus="yes">
        <source>saved %n parameter(s) of %1 to %2</source>
        <translation>
            <numerusform>saved %n parameter of %1 to %2</numerusform>
            <numerusform>saved %n parameters of %1 to %2</numerusform>
        </translation>
    </message>
    <message>
        <source>the controller holds every value of the profile</source>
        <translation>the controller holds every value of the profile</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) differ (controller -&gt; profile)</source>
        <translation>
            <numerusform>%n value differs (controller -&gt; profile)</numerusform>
            <numerusform>%n values differ (controller -&gt; profile)</numerusform>
        </translation>
    </message>
    <message>
        <source>note: device.baud changes the controller&apos;s serial side only</source>
        <translation>note: device.baud changes the controller&apos;s serial side only</translation>
    </message>
    <message>
        <source>not applied (needs --include-link): %1</source>
        <translation>not applied (needs --include-link): %1</translation>
    </message>
    <message>
        <source>will write %1</source>
        <translation>will write %1</translation>
    </message>
    <message>
        <source>the controller already holds the profile&apos;s values</source>
        <translation>the controller already holds the profile&apos;s values</translation>
    </message>
    <message numerus="yes">
        <source>Write these %n value(s) to the controller? [y/N] </source>
        <translation>
            <numerusform>Write %n value to the controller? [y/N] </numerusform>
            <numerusform>Write these %n values to the controller? [y/N] </numerusform>
        </translation>
    </message>
    <message>
        <source>not confirmed: nothing was written</source>
        <translation>not confirmed: nothing was written</translation>
    </message>
    <message>
        <source>no answer on standard input: nothing was written (use --yes)</source>
        <translation>no answer on standard input: nothing was written (use --yes)</translation>
    </message>
    <message>
        <source>not saved to flash: the controller forgets these values at power-off (use --save-to-flash)</source>
        <translation>not saved to flash: the controller forgets these values at power-off (use --save-to-flash)</translation>
    </message>
    <message>
        <source>report needs exactly one file (.pdf or .html)</source>
        <translation>report needs exactly one file (.pdf or .html)</translation>
    </message>
    <message>
        <source>%1: the report is written as .pdf or .html</source>
        <translation>%1: the report is written as .pdf or .html</translation>
    </message>
    <message>
        <source>no report: the controller could not be read completely</source>
        <translation>no report: the controller could not be read completely</translation>
    </message>
    <message>
        <source>report written to %1</source>
        <translation>report written to %1</translation>
    </message>
    <message>
        <source>unknown command &apos;%1&apos; (%2)</source>
        <translation>unknown command &apos;%1&apos; (%2)</translation>
    </message>
    <message>
        <source>diff needs one profile file (compared with the controller) or two (compared with each other)</source>
        <translation>diff needs one profile file (compared with the controller) or two (compared with each other)</translation>
    </message>
    <message>
        <source>left out of the comparison:</source>
        <translation>left out of the comparison:</translation>
    </message>
    <message numerus="yes">
        <source>the controller holds every value both maps have; %n left out</source>
        <translation>
            <numerusform>the controller holds every value both maps have; %n left out</numerusform>
            <numerusform>the controller holds every value both maps have; %n left out</numerusform>
        </translation>
    </message>
    <message>
        <source>nothing was compared</source>
        <translation>nothing was compared</translation>
    </message>
    <message>
        <source>A = %1: &quot;%2&quot;, register map %3</source>
        <translation>A = %1: &quot;%2&quot;, register map %3</translation>
    </message>
    <message>
        <source>B = %1: &quot;%2&quot;, register map %3</source>
        <translation>B = %1: &quot;%2&quot;, register map %3</translation>
    </message>
    <message>
        <source>differ (A -&gt; B):</source>
        <translation>differ (A -&gt; B):</translation>
    </message>
    <message>
        <source>only in A (%1):</source>
        <translation>only in A (%1):</translation>
    </message>
    <message>
        <source>only in B (%1):</source>
        <translation>only in B (%1):</translation>
    </message>
    <message>
        <source>not settings of register map %1, or out of its range (as the files hold them, A -&gt; B):</source>
        <translation>not settings of register map %1, or out of its range (as the files hold them, A -&gt; B):</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(none)</translation>
    </message>
    <message>
        <source>the two profiles hold the same values</source>
        <translation>the two profiles hold the same values</translation>
    </message>
    <message>
        <source>%1 differ, %2 only in A, %3 only in B, %4 outside this map</source>
        <translation>%1 differ, %2 only in A, %3 only in B, %4 outside this map</translation>
    </message>
    <message>
        <source>not applied:</source>
        <translation>not applied:</translation>
    </message>
    <message>
        <source>the profile holds no setting of this map: nothing to apply</source>
        <translation>the profile holds no setting of this map: nothing to apply</translation>
    </message>
    <message>
        <source>the controller already holds every value both maps have</source>
        <translation>the controller already holds every value both maps have</translation>
    </message>
    <message>
        <source>no report: %1 is not a profile StepCom can read</source>
        <translation>no report: %1 is not a profile StepCom can read</translation>
    </message>
    <message>
        <source>not in the report:</source>
        <translation>not in the report:</translation>
    </message>
    <message>
        <source>report written to %1, made from the profile file %2 (no controller was read)</source>
        <translation>report written to %1, made from the profile file %2 (no controller was read)</translation>
    </message>
    <message>
        <source>no backup of the controller&apos;s settings could be saved (%1): nothing was written (--no-backup applies without one)</source>
        <translation>no backup of the controller&apos;s settings could be saved (%1): nothing was written (--no-backup applies without one)</translation>
    </message>
    <message>
        <source>backup of the controller&apos;s settings: %1</source>
        <translation>backup of the controller&apos;s settings: %1</translation>
    </message>
    <message>
        <source>no report: the checklist beside the profile cannot be read</source>
        <translation>no report: the checklist beside the profile cannot be read</translation>
    </message>
    <message>
        <source>with the commissioning checklist %1: %2</source>
        <translation>with the commissioning checklist %1: %2</translation>
    </message>
    <message>
        <source>%1: sent (add --wait to wait for how it ends)</source>
        <translation>%1: sent (add --wait to wait for how it ends)</translation>
    </message>
    <message>
        <source>--wait: %1 has no end to wait for (single move, home, home in order, return to data zero, arc and line have one)</source>
        <translation>--wait: %1 has no end to wait for (single move, home, home in order, return to data zero, arc and line have one)</translation>
    </message>
    <message>
        <source>no backup of the controller&apos;s settings could be saved (%1): nothing was done (--no-backup goes on without one)</source>
        <translation>no backup of the controller&apos;s settings could be saved (%1): nothing was done (--no-backup goes on without one)</translation>
    </message>
    <message>
        <source>move needs one motor: move motor1 --by D or --to X</source>
        <translation>move needs one motor: move motor1 --by D or --to X</translation>
    </message>
    <message>
        <source>there is no motor %1 (this map has motor1 .. motor%2)</source>
        <translation>there is no motor %1 (this map has motor1 .. motor%2)</translation>
    </message>
    <message>
        <source>move needs exactly one of --by D and --to X</source>
        <translation>move needs exactly one of --by D and --to X</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number</source>
        <translation>%1: &apos;%2&apos; is not a number</translation>
    </message>
    <message>
        <source>id %1: %2</source>
        <translation>id %1: %2</translation>
    </message>
    <message>
        <source>== device id %1 ==</source>
        <translation>== device id %1 ==</translation>
    </message>
    <message>
        <source>assign-id: give the new id with --to N, and one --id (the id the controller answers at now, 1 from the factory)</source>
        <translation>assign-id: give the new id with --to N, and one --id (the id the controller answers at now, 1 from the factory)</translation>
    </message>
    <message>
        <source>assign-id: the controller already has id %1</source>
        <translation>assign-id: the controller already has id %1</translation>
    </message>
    <message>
        <source>link: %1</source>
        <translation>link: %1</translation>
    </message>
    <message>
        <source>saved the settings of %1 to %2</source>
        <translation>saved the settings of %1 to %2</translation>
    </message>
    <message>
        <source>report --from makes the report of one profile file: give one --id</source>
        <translation>report --from makes the report of one profile file: give one --id</translation>
    </message>
    <message>
        <source>no report: not every controller could be read completely</source>
        <translation>no report: not every controller could be read completely</translation>
    </message>
    <message numerus="yes">
        <source>report of %n controller(s) written to %1</source>
        <translation>
            <numerusform>report of %n controller written to %1</numerusform>
            <numerusform>report of %n controllers written to %1</numerusform>
        </translation>
    </message>
    <message>
        <source>not supported by this controller (left out): %1</source>
        <translation>not supported by this controller (left out): %1</translation>
    </message>
    <message>
        <source>nothing was saved: %1</source>
        <translation>nothing was saved: %1</translation>
    </message>
    <message numerus="yes">
        <source>Write these %n value(s) to id %1? [y/N] </source>
        <translation>
            <numerusform>Write these %n value to id %1? [y/N] </numerusform>
            <numerusform>Write these %n values to id %1? [y/N] </numerusform>
        </translation>
    </message>
    <message>
        <source>note: %1</source>
        <translation>note: %1</translation>
    </message>
    <message>
        <source>%1 is not supported by this controller</source>
        <translation>%1 is not supported by this controller</translation>
    </message>
    <message>
        <source>scan takes no arguments (&apos;%1&apos;): give --bauds, --parity and --ids</source>
        <translation>scan takes no arguments (&apos;%1&apos;): give --bauds, --parity and --ids</translation>
    </message>
    <message>
        <source>replay needs a log and one of --events, --at TIME or --diff T1 T2</source>
        <translation>replay needs a log and one of --events, --at TIME or --diff T1 T2</translation>
    </message>
    <message>
        <source>--entry: the bundle holds no log %1 (it holds: %2)</source>
        <translation>--entry: the bundle holds no log %1 (it holds: %2)</translation>
    </message>
    <message>
        <source>replaying %1 (logs in the bundle: %2; --entry NAME for another)</source>
        <translation>replaying %1 (logs in the bundle: %2; --entry NAME for another)</translation>
    </message>
    <message>
        <source>warning: %1</source>
        <translation>warning: %1</translation>
    </message>
    <message>
        <source>at %1, link %2</source>
        <translation>at %1, link %2</translation>
    </message>
    <message>
        <source>up</source>
        <translation>up</translation>
    </message>
    <message>
        <source>down</source>
        <translation>down</translation>
    </message>
    <message>
        <source>answering</source>
        <translation>answering</translation>
    </message>
    <message>
        <source>not answering</source>
        <translation>not answering</translation>
    </message>
    <message>
        <source>last error at %1: %2</source>
        <translation>last error at %1: %2</translation>
    </message>
    <message>
        <source>(last written: %1)</source>
        <translation>(last written: %1)</translation>
    </message>
    <message>
        <source>from %1 to %2, changes: %3</source>
        <translation>from %1 to %2, changes: %3</translation>
    </message>
    <message>
        <source>bundle needs the name of the zip file to write</source>
        <translation>bundle needs the name of the zip file to write</translation>
    </message>
    <message>
        <source>wrote %1 (%2):</source>
        <translation>wrote %1 (%2):</translation>
    </message>
    <message>
        <source>%1: give one device id; several ids work with read, monitor, diff, apply, dump, report, bundle and command (without --wait)</source>
        <translation>%1: give one device id; several ids work with read, monitor, diff, apply, dump, report, bundle and command (without --wait)</translation>
    </message>
    <message>
        <source>--profile: %1 does not exist</source>
        <translation>--profile: %1 does not exist</translation>
    </message>
    <message>
        <source>the profile goes into the bundle as it is, but not into the report</source>
        <translation>the profile goes into the bundle as it is, but not into the report</translation>
    </message>
    <message>
        <source>no bundle: not every controller could be read completely (without --port, --tcp or --sim the bundle has no controller in its report)</source>
        <translation>no bundle: not every controller could be read completely (without --port, --tcp or --sim the bundle has no controller in its report)</translation>
    </message>
    <message>
        <source>no machine report: no controller was read (--port, --tcp or --sim) and no profile was given (--profile)</source>
        <translation>no machine report: no controller was read (--port, --tcp or --sim) and no profile was given (--profile)</translation>
    </message>
    <message>
        <source>check: %1</source>
        <translation>check: %1</translation>
    </message>
    <message>
        <source>nothing was written: the window asks before writing these values; add --yes to write them anyway</source>
        <translation>nothing was written: the window asks before writing these values; add --yes to write them anyway</translation>
    </message>
    <message>
        <source>what the values are checked against could not be read: nothing was written</source>
        <translation>what the values are checked against could not be read: nothing was written</translation>
    </message>
    <message>
        <source>%1: %2 has more decimals than motor %3 counts in (steps of %4 %5): nothing was moved</source>
        <translation>%1: %2 has more decimals than motor %3 counts in (steps of %4 %5): nothing was moved</translation>
    </message>
    <message numerus="yes">
        <source>(the same for %n more read(s) of this command)</source>
        <translation>
            <numerusform>(the same for %n more read of this command)</numerusform>
            <numerusform>(the same for %n more reads of this command)</numerusform>
        </translation>
    </message>
    <message>
        <source>next commands: stepcomctl %1 ...</source>
        <translation>next commands: stepcomctl %1 ...</translation>
    </message>
    <message>
        <source>id %1 lasts until the power is switched off, then the controller answers at the id in its flash again (id 1 from the factory); add --save-to-flash to keep it</source>
        <translation>id %1 lasts until the power is switched off, then the controller answers at the id in its flash again (id 1 from the factory); add --save-to-flash to keep it</translation>
    </message>
    <message>
        <source>scan: give the line to scan: --port, --rtu-tcp, --tcp or --sim</source>
        <translation>scan: give the line to scan: --port, --rtu-tcp, --tcp or --sim</translation>
    </message>
    <message>
        <source>it has no serial line here</source>
        <translation>it has no serial line here</translation>
    </message>
    <message>
        <source>ports takes no arguments (&apos;%1&apos;)</source>
        <translation>ports takes no arguments (&apos;%1&apos;)</translation>
    </message>
    <message>
        <source>no serial port found: is the USB adapter plugged in? (its driver&apos;s messages: sudo dmesg | tail)</source>
        <translation>no serial port found: is the USB adapter plugged in? (its driver&apos;s messages: sudo dmesg | tail)</translation>
    </message>
    <message>
        <source>S/N %1</source>
        <translation>S/N %1</translation>
    </message>
    <message>
        <source>stable name: %1</source>
        <translation>stable name: %1</translation>
    </message>
    <message>
        <source>no permission to open it: add yourself to its group (ls -l %1; usually dialout), then log in again</source>
        <translation>no permission to open it: add yourself to its group (ls -l %1; usually dialout), then log in again</translation>
    </message>
    <message>
        <source>open it with: stepcomctl --port %1 read device.id</source>
        <translation>open it with: stepcomctl --port %1 read device.id</translation>
    </message>
    <message>
        <source>listen takes no arguments, only --port, --baud, --parity, --seconds, --json and --log</source>
        <translation>listen takes no arguments, only --port, --baud, --parity, --seconds, --json and --log</translation>
    </message>
    <message>
        <source>listen hears a serial line: give --port (a line StepCom does not drive; --tcp and --sim have no other master to hear)</source>
        <translation>listen hears a serial line: give --port (a line StepCom does not drive; --tcp and --sim have no other master to hear)</translation>
    </message>
    <message>
        <source>%1 (at %2)</source>
        <translation>%1 (at %2)</translation>
    </message>
    <message>
        <source>cycles done: %1; cycle time min %2 s, median %3 s, max %4 s; %5 s in all</source>
        <translation>cycles done: %1; cycle time min %2 s, median %3 s, max %4 s; %5 s in all</translation>
    </message>
    <message>
        <source>cycle %1 %2: %3</source>
        <translation>cycle %1 %2: %3</translation>
    </message>
    <message>
        <source>cycle %1 done in %2 s</source>
        <translation>cycle %1 done in %2 s</translation>
    </message>
    <message>
        <source>the run could not start: not connected</source>
        <translation>the run could not start: not connected</translation>
    </message>
    <message>
        <source>run needs one sequence file: run FILE</source>
        <translation>run needs one sequence file: run FILE</translation>
    </message>
    <message>
        <source>the sequence file was refused: nothing was sent</source>
        <translation>the sequence file was refused: nothing was sent</translation>
    </message>
    <message>
        <source>Run it? The machine will move. [y/N] </source>
        <translation>Run it? The machine will move. [y/N] </translation>
    </message>
    <message>
        <source>not confirmed: nothing was sent</source>
        <translation>not confirmed: nothing was sent</translation>
    </message>
    <message>
        <source>no answer on standard input: nothing was sent (use --yes)</source>
        <translation>no answer on standard input: nothing was sent (use --yes)</translation>
    </message>
    <message>
        <source>%1 needs one motor: %1 motorN (N from 1 to %2)</source>
        <translation>%1 needs one motor: %1 motorN (N from 1 to %2)</translation>
    </message>
    <message>
        <source>--distance: &apos;%1&apos; is not a positive distance</source>
        <translation>--distance: &apos;%1&apos; is not a positive distance</translation>
    </message>
    <message>
        <source>--%1: &apos;%2&apos; is not a positive whole number</source>
        <translation>--%1: &apos;%2&apos; is not a positive whole number</translation>
    </message>
    <message>
        <source>Run it? The axis will move. [y/N] </source>
        <translation>Run it? The axis will move. [y/N] </translation>
    </message>
    <message>
        <source>no answer on standard input: nothing was moved (use --yes)</source>
        <translation>no answer on standard input: nothing was moved (use --yes)</translation>
    </message>
    <message>
        <source>not confirmed: nothing was moved</source>
        <translation>not confirmed: nothing was moved</translation>
    </message>
    <message>
        <source>--apply: nothing kept its steps, nothing was written</source>
        <translation>--apply: nothing kept its steps, nothing was written</translation>
    </message>
    <message>
        <source>%1, %2: gauge (mm)? </source>
        <translation>%1, %2: gauge (mm)? </translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a number: type the gauge&apos;s reading</source>
        <translation>&apos;%1&apos; is not a number: type the gauge&apos;s reading</translation>
    </message>
    <message>
        <source>check-steps: %1</source>
        <translation>check-steps: %1</translation>
    </message>
</context>
<context>
    <name>stepcom::CtlScan</name>
    <message numerus="yes">
        <source>scanning %1: %n id(s), %2 ms a probe</source>
        <translation>
            <numerusform>scanning %1: %n id, %2 ms a probe</numerusform>
            <numerusform>scanning %1: %n ids, %2 ms a probe</numerusform>
        </translation>
    </message>
    <message>
        <source>found %1</source>
        <translation>found %1</translation>
    </message>
    <message>
        <source>over a network the converter&apos;s or gateway&apos;s serial line has its own baud and parity: only the ids are scanned</source>
        <translation>over a network the converter&apos;s or gateway&apos;s serial line has its own baud and parity: only the ids are scanned</translation>
    </message>
    <message>
        <source>at most about %1 s when nobody answers; a scan only reads</source>
        <translation>at most about %1 s when nobody answers; a scan only reads</translation>
    </message>
    <message>
        <source>%1 of %2 probed (id %3)</source>
        <translation>%1 of %2 probed (id %3)</translation>
    </message>
    <message>
        <source>scan stopped: %1</source>
        <translation>scan stopped: %1</translation>
    </message>
    <message numerus="yes">
        <source>%n controller(s) found in %1 s</source>
        <translation>
            <numerusform>%n controller found in %1 s</numerusform>
            <numerusform>%n controllers found in %1 s</numerusform>
        </translation>
    </message>
    <message>
        <source>No controller answered. Check the power, the wiring (A and B swapped?), the port, and for a controller that answers slowly give --probe-timeout.</source>
        <translation>No controller answered. Check the power, the wiring (A and B swapped?), the port, and for a controller that answers slowly give --probe-timeout.</translation>
    </message>
    <message>
        <source>id</source>
        <translation>id</translation>
    </message>
    <message>
        <source>baud</source>
        <translation>baud</translation>
    </message>
    <message>
        <source>parity</source>
        <translation>parity</translation>
    </message>
    <message>
        <source>answer</source>
        <translation>answer</translation>
    </message>
    <message>
        <source>controller</source>
        <translation>controller</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>id %1 answered after %2 ms, later than the probe waited: connect with --timeout %3</source>
        <translation>id %1 answered after %2 ms, later than the probe waited: connect with --timeout %3</translation>
    </message>
</context>
<context>
    <name>stepcom::DerivedValues</name>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>%1 min %2 s</source>
        <translation>%1 min %2 s</translation>
    </message>
    <message>
        <source>%1 h %2 min</source>
        <translation>%1 h %2 min</translation>
    </message>
    <message>
        <source>Pulses per revolution:</source>
        <translation>Pulses per revolution:</translation>
    </message>
    <message>
        <source>Pulse rate at the set speed:</source>
        <translation>Pulse rate at the set speed:</translation>
    </message>
    <message>
        <source>Linear speed:</source>
        <translation>Linear speed:</translation>
    </message>
    <message>
        <source>Revolutions per move:</source>
        <translation>Revolutions per move:</translation>
    </message>
    <message>
        <source>Pulses per move:</source>
        <translation>Pulses per move:</translation>
    </message>
    <message>
        <source>Ramp to the set speed:</source>
        <translation>Ramp to the set speed:</translation>
    </message>
    <message>
        <source>Estimated move time:</source>
        <translation>Estimated move time:</translation>
    </message>
    <message>
        <source>360 / step angle × microsteps</source>
        <translation>360 / step angle × microsteps</translation>
    </message>
    <message>
        <source>Speed (rpm) × pulses per revolution / 60: what the driver must accept</source>
        <translation>Speed (rpm) × pulses per revolution / 60: what the driver must accept</translation>
    </message>
    <message>
        <source>Speed (rpm) × pitch / 60</source>
        <translation>Speed (rpm) × pitch / 60</translation>
    </message>
    <message>
        <source>Speed (rpm) × pitch</source>
        <translation>Speed (rpm) × pitch</translation>
    </message>
    <message>
        <source>Move distance / pitch</source>
        <translation>Move distance / pitch</translation>
    </message>
    <message>
        <source>Move distance / pitch × pulses per revolution, in whole pulses as the controller sends them</source>
        <translation>Move distance / pitch × pulses per revolution, in whole pulses as the controller sends them</translation>
    </message>
    <message>
        <source>(Pulse rate − start frequency) / accel/decel frequency: the rate rises by the accel/decel frequency every millisecond; braking takes as long</source>
        <translation>(Pulse rate − start frequency) / accel/decel frequency: the rate rises by the accel/decel frequency every millisecond; braking takes as long</translation>
    </message>
    <message>
        <source>A single move with its ramps up and down, as the simulator runs it (start frequency, accel/decel frequency per millisecond, speed)</source>
        <translation>A single move with its ramps up and down, as the simulator runs it (start frequency, accel/decel frequency per millisecond, speed)</translation>
    </message>
    <message>
        <source>units</source>
        <translation>units</translation>
    </message>
    <message>
        <source>%1 pulses/rev</source>
        <translation>%1 pulses/rev</translation>
    </message>
    <message>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <source>%1 %2/s</source>
        <translation>%1 %2/s</translation>
    </message>
    <message>
        <source>%1 %2/min</source>
        <translation>%1 %2/min</translation>
    </message>
    <message>
        <source>%1 rev</source>
        <translation>%1 rev</translation>
    </message>
    <message>
        <source>%1 pulses</source>
        <translation>%1 pulses</translation>
    </message>
    <message>
        <source>none (start frequency ≥ pulse rate)</source>
        <translation>none (start frequency ≥ pulse rate)</translation>
    </message>
</context>
<context>
    <name>stepcom::DeviceClient</name>
    <message>
        <source>nothing readable among the parameters asked for</source>
        <translation>nothing readable among the parameters asked for</translation>
    </message>
    <message>
        <source>read block %1/%2</source>
        <translation>read block %1/%2</translation>
    </message>
    <message>
        <source>unknown parameter</source>
        <translation>unknown parameter</translation>
    </message>
    <message>
        <source>%1 is read-only</source>
        <translation>%1 is read-only</translation>
    </message>
    <message>
        <source>%1 is given twice</source>
        <translation>%1 is given twice</translation>
    </message>
    <message>
        <source>could not reopen the port at the new baud: %1</source>
        <translation>could not reopen the port at the new baud: %1</translation>
    </message>
    <message>
        <source>%1: wrote %2 but the controller holds %3</source>
        <translation>%1: wrote %2 but the controller holds %3</translation>
    </message>
    <message>
        <source>%1: wrote %2 but could not read it back</source>
        <translation>%1: wrote %2 but could not read it back</translation>
    </message>
</context>
<context>
    <name>stepcom::DeviceListDock</name>
    <message>
        <source>Device id %1 is already on the list.</source>
        <translation>Device id %1 is already on the list.</translation>
    </message>
    <message>
        <source>Devices on the line</source>
        <translation>Devices on the line</translation>
    </message>
    <message>
        <source>Id</source>
        <translation>Id</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>State</source>
        <translation>State</translation>
    </message>
    <message>
        <source>Referenced</source>
        <translation>Referenced</translation>
    </message>
    <message>
        <source>Errors</source>
        <translation>Errors</translation>
    </message>
    <message>
        <source>Add device</source>
        <translation>Add device</translation>
    </message>
    <message>
        <source>Device id to add</source>
        <translation>Device id to add</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>not connected</translation>
    </message>
    <message>
        <source>answering (in view)</source>
        <translation>answering (in view)</translation>
    </message>
    <message>
        <source>not answering (in view)</source>
        <translation>not answering (in view)</translation>
    </message>
    <message>
        <source>asking (in view)</source>
        <translation>asking (in view)</translation>
    </message>
    <message>
        <source>answering</source>
        <translation>answering</translation>
    </message>
    <message>
        <source>not answering</source>
        <translation>not answering</translation>
    </message>
    <message>
        <source>asking</source>
        <translation>asking</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unknown</translation>
    </message>
    <message>
        <source>no</source>
        <translation>no</translation>
    </message>
    <message>
        <source>motor %1</source>
        <translation>motor %1</translation>
    </message>
    <message>
        <source>Device ids are 1 to 255, not %1.</source>
        <translation>Device ids are 1 to 255, not %1.</translation>
    </message>
    <message>
        <source>Other devices read every:</source>
        <translation>Other devices read every:</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>The device in view is read at the live rate; each of the others in turn, at most this often</source>
        <translation>The device in view is read at the live rate; each of the others in turn, at most this often</translation>
    </message>
    <message>
        <source>running: %1</source>
        <translation>running: %1</translation>
    </message>
    <message>
        <source>%1; restarted %2</source>
        <translation>%1; restarted %2</translation>
    </message>
</context>
<context>
    <name>stepcom::DevicePage</name>
    <message>
        <source>Device</source>
        <translation>Device</translation>
    </message>
    <message>
        <source>ID %1</source>
        <translation>ID %1</translation>
    </message>
    <message>
        <source>ID %1 at %2 baud</source>
        <translation>ID %1 at %2 baud</translation>
    </message>
    <message>
        <source>The controller holds %1</source>
        <translation>The controller holds %1</translation>
    </message>
    <message>
        <source>Not read yet</source>
        <translation>Not read yet</translation>
    </message>
    <message>
        <source>Changing the controller to %1…</source>
        <translation>Changing the controller to %1…</translation>
    </message>
    <message>
        <source>The controller answers at %1. Save to flash to keep this after a power cycle.</source>
        <translation>The controller answers at %1. Save to flash to keep this after a power cycle.</translation>
    </message>
    <message>
        <source>The controller does not answer with the new settings (%1). It may be using them anyway. Reconnect with the old settings (%2), or connect with the new ones on the Connection page.</source>
        <translation>The controller does not answer with the new settings (%1). It may be using them anyway. Reconnect with the old settings (%2), or connect with the new ones on the Connection page.</translation>
    </message>
    <message>
        <source>Reconnecting with the old settings (%1)…</source>
        <translation>Reconnecting with the old settings (%1)…</translation>
    </message>
    <message>
        <source>Connected again with the old settings.</source>
        <translation>Connected again with the old settings.</translation>
    </message>
    <message>
        <source>Reconnecting with the old settings failed: %1.</source>
        <translation>Reconnecting with the old settings failed: %1.</translation>
    </message>
    <message>
        <source>Saving to flash…</source>
        <translation>Saving to flash…</translation>
    </message>
    <message>
        <source>Saved to flash: the controller keeps its settings after a power cycle.</source>
        <translation>Saved to flash: the controller keeps its settings after a power cycle.</translation>
    </message>
    <message>
        <source>Saving to flash failed; see the messages.</source>
        <translation>Saving to flash failed; see the messages.</translation>
    </message>
    <message>
        <source>Restoring the factory settings…</source>
        <translation>Restoring the factory settings…</translation>
    </message>
    <message>
        <source>Factory settings restored; StepCom reads the controller again.</source>
        <translation>Factory settings restored; StepCom reads the controller again.</translation>
    </message>
    <message>
        <source>Restoring the factory settings failed; see the messages.</source>
        <translation>Restoring the factory settings failed; see the messages.</translation>
    </message>
    <message>
        <source>Change device ID and baud rate</source>
        <translation>Change device ID and baud rate</translation>
    </message>
    <message>
        <source>Change the controller from %1 to %2?</source>
        <translation>Change the controller from %1 to %2?</translation>
    </message>
    <message>
        <source>&amp;Change</source>
        <translation>&amp;Change</translation>
    </message>
    <message>
        <source>motors 1 to %1</source>
        <translation>motors 1 to %1</translation>
    </message>
    <message>
        <source>the motor</source>
        <translation>the motor</translation>
    </message>
    <message>
        <source>every motor parameter of %1: step angle, microsteps, start and accel/decel frequency, direction, speed, pitch, move distance</source>
        <translation>every motor parameter of %1: step angle, microsteps, start and accel/decel frequency, direction, speed, pitch, move distance</translation>
    </message>
    <message>
        <source>the limit and home inputs</source>
        <translation>the limit and home inputs</translation>
    </message>
    <message>
        <source>the homing order</source>
        <translation>the homing order</translation>
    </message>
    <message>
        <source>the arc and line interpolation setup</source>
        <translation>the arc and line interpolation setup</translation>
    </message>
    <message>
        <source>the system mode and its number of round trips</source>
        <translation>the system mode and its number of round trips</translation>
    </message>
    <message>
        <source>These settings in the controller are replaced by the factory values:</source>
        <translation>These settings in the controller are replaced by the factory values:</translation>
    </message>
    <message>
        <source>The device ID (%1) and the baud rate (%2) are kept, so StepCom stays connected. Edits not written yet stay in StepCom. The flash keeps the old settings until you save to flash.</source>
        <translation>The device ID (%1) and the baud rate (%2) are kept, so StepCom stays connected. Edits not written yet stay in StepCom. The flash keeps the old settings until you save to flash.</translation>
    </message>
    <message>
        <source>Restore factory settings</source>
        <translation>Restore factory settings</translation>
    </message>
    <message>
        <source>Restore the controller&apos;s factory settings?</source>
        <translation>Restore the controller&apos;s factory settings?</translation>
    </message>
    <message>
        <source>&amp;Restore factory settings</source>
        <translation>&amp;Restore factory settings</translation>
    </message>
    <message>
        <source>Device ID and baud rate</source>
        <translation>Device ID and baud rate</translation>
    </message>
    <message>
        <source>Flash memory</source>
        <translation>Flash memory</translation>
    </message>
    <message>
        <source>Factory settings</source>
        <translation>Factory settings</translation>
    </message>
    <message>
        <source>Device &amp;ID:</source>
        <translation>Device &amp;ID:</translation>
    </message>
    <message>
        <source>&amp;Baud rate:</source>
        <translation>&amp;Baud rate:</translation>
    </message>
    <message>
        <source>The device ID matters on RS-485, where several controllers share the bus. On Modbus TCP only the ID can be changed here.</source>
        <translation>The device ID matters on RS-485, where several controllers share the bus. On Modbus TCP only the ID can be changed here.</translation>
    </message>
    <message>
        <source>&amp;Apply ID and baud…</source>
        <translation>&amp;Apply ID and baud…</translation>
    </message>
    <message>
        <source>Reconnect with the &amp;old settings</source>
        <translation>Reconnect with the &amp;old settings</translation>
    </message>
    <message>
        <source>Written values take effect at once but live in working memory: without saving to flash, the controller forgets them when it is switched off.</source>
        <translation>Written values take effect at once but live in working memory: without saving to flash, the controller forgets them when it is switched off.</translation>
    </message>
    <message>
        <source>Changes not saved to flash.</source>
        <translation>Changes not saved to flash.</translation>
    </message>
    <message>
        <source>&amp;Save to flash</source>
        <translation>&amp;Save to flash</translation>
    </message>
    <message>
        <source>Puts every motor parameter, the limits, the homing order, the interpolation setup and the mode back to the factory values. The device ID and baud rate are kept.</source>
        <translation>Puts every motor parameter, the limits, the homing order, the interpolation setup and the mode back to the factory values. The device ID and baud rate are kept.</translation>
    </message>
    <message>
        <source>Restore &amp;factory settings…</source>
        <translation>Restore &amp;factory settings…</translation>
    </message>
    <message>
        <source>The controller switches at once. StepCom follows it and checks that it answers; if it does not, you can reconnect with the old settings.

Every other master on the bus must use the new settings too, and no other device may use the new ID. Unsaved, they last until the next power-off.</source>
        <translation>The controller switches at once. StepCom follows it and checks that it answers; if it does not, you can reconnect with the old settings.

Every other master on the bus must use the new settings too, and no other device may use the new ID. Unsaved, they last until the next power-off.</translation>
    </message>
    <message>
        <source>Save to flash at the new settings (else lost at power-off)</source>
        <translation>Save to flash at the new settings (else lost at power-off)</translation>
    </message>
</context>
<context>
    <name>stepcom::DeviceSession</name>
    <message>
        <source>Cannot connect: %1</source>
        <translation>Cannot connect: %1</translation>
    </message>
    <message>
        <source>Link lost: %1</source>
        <translation>Link lost: %1</translation>
    </message>
    <message>
        <source>Cannot start the built-in simulator: %1</source>
        <translation>Cannot start the built-in simulator: %1</translation>
    </message>
    <message>
        <source>disconnected by the user</source>
        <translation>disconnected by the user</translation>
    </message>
    <message>
        <source>Reading failed: %1</source>
        <translation>Reading failed: %1</translation>
    </message>
    <message numerus="yes">
        <source>Wrote and verified %n parameter(s)</source>
        <translation>
            <numerusform>Wrote and verified %n parameter</numerusform>
            <numerusform>Wrote and verified %n parameters</numerusform>
        </translation>
    </message>
    <message>
        <source>Unknown command %1</source>
        <translation>Unknown command %1</translation>
    </message>
    <message>
        <source>%1: done</source>
        <translation>%1: done</translation>
    </message>
    <message>
        <source>E-STOP: not connected, nothing was sent</source>
        <translation>E-STOP: not connected, nothing was sent</translation>
    </message>
    <message>
        <source>emergency stop</source>
        <translation>emergency stop</translation>
    </message>
    <message>
        <source>E-STOP sent</source>
        <translation>E-STOP sent</translation>
    </message>
    <message>
        <source>The controller answers at %1</source>
        <translation>The controller answers at %1</translation>
    </message>
    <message>
        <source>The controller does not answer with the new settings: %1</source>
        <translation>The controller does not answer with the new settings: %1</translation>
    </message>
    <message>
        <source>switching to %1</source>
        <translation>switching to %1</translation>
    </message>
    <message>
        <source>Read %1 in %2</source>
        <comment>%1: n parameters, %2: n requests</comment>
        <translation>Read %1 in %2</translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s)</source>
        <translation>
            <numerusform>%n parameter</numerusform>
            <numerusform>%n parameters</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n request(s)</source>
        <translation>
            <numerusform>%n request</numerusform>
            <numerusform>%n requests</numerusform>
        </translation>
    </message>
    <message>
        <source>the built-in simulator was replaced</source>
        <translation>the built-in simulator was replaced</translation>
    </message>
    <message>
        <source>this program has no built-in simulator</source>
        <translation>this program has no built-in simulator</translation>
    </message>
    <message>
        <source>the page was left</source>
        <translation>the page was left</translation>
    </message>
    <message>
        <source>the window lost focus</source>
        <translation>the window lost focus</translation>
    </message>
    <message>
        <source>the window closes</source>
        <translation>the window closes</translation>
    </message>
    <message>
        <source>Opened %1; asking the controller</source>
        <translation>Opened %1; asking the controller</translation>
    </message>
    <message>
        <source>The port is open, but the controller at %1 does not answer.</source>
        <translation>The port is open, but the controller at %1 does not answer.</translation>
    </message>
    <message>
        <source>The controller answers.</source>
        <translation>The controller answers.</translation>
    </message>
    <message>
        <source>%1: sent</source>
        <translation>%1: sent</translation>
    </message>
    <message numerus="yes">
        <source>E-STOP sent to %n controller(s): id %1</source>
        <translation>
            <numerusform>E-STOP sent to %n controller: id %1</numerusform>
            <numerusform>E-STOP sent to %n controllers: id %1</numerusform>
        </translation>
    </message>
    <message>
        <source>E-STOP acknowledged by every controller: id %1</source>
        <translation>E-STOP acknowledged by every controller: id %1</translation>
    </message>
    <message>
        <source>E-STOP NOT acknowledged by id %1 (%2); acknowledged by: %3</source>
        <translation>E-STOP NOT acknowledged by id %1 (%2); acknowledged by: %3</translation>
    </message>
    <message>
        <source>none</source>
        <translation>none</translation>
    </message>
    <message>
        <source>Device id %1 is not on this line (%2)</source>
        <translation>Device id %1 is not on this line (%2)</translation>
    </message>
    <message>
        <source>showing device %1</source>
        <translation>showing device %1</translation>
    </message>
    <message>
        <source>Device %1: %2</source>
        <translation>Device %1: %2</translation>
    </message>
    <message>
        <source>The link is back at %1 (attempt %2): reading the status, then everything</source>
        <translation>The link is back at %1 (attempt %2): reading the status, then everything</translation>
    </message>
    <message>
        <source>Reconnecting cancelled: Connect tries again.</source>
        <translation>Reconnecting cancelled: Connect tries again.</translation>
    </message>
    <message>
        <source>E-STOP: the link is down, the controller did NOT get it; it is sent first when the link is back</source>
        <translation>E-STOP: the link is down, the controller did NOT get it; it is sent first when the link is back</translation>
    </message>
    <message>
        <source>Trying to connect again on its own (Cancel stops it).</source>
        <translation>Trying to connect again on its own (Cancel stops it).</translation>
    </message>
    <message>
        <source>The controller refuses reads that cover reserved registers; from now on only its listed registers are read (a few more requests).</source>
        <translation>The controller refuses reads that cover reserved registers; from now on only its listed registers are read (a few more requests).</translation>
    </message>
    <message>
        <source>%1 (register %2) is not supported by this controller: it refuses to read it. It is left out from now on.</source>
        <translation>%1 (register %2) is not supported by this controller: it refuses to read it. It is left out from now on.</translation>
    </message>
    <message>
        <source>Device id %1: %2</source>
        <translation>Device id %1: %2</translation>
    </message>
    <message>
        <source>it refuses reads that cover reserved registers, so only its listed registers are read</source>
        <translation>it refuses reads that cover reserved registers, so only its listed registers are read</translation>
    </message>
    <message>
        <source>it does not support %1</source>
        <translation>it does not support %1</translation>
    </message>
    <message>
        <source>Known from an earlier connection to this controller: %1.</source>
        <translation>Known from an earlier connection to this controller: %1.</translation>
    </message>
    <message>
        <source>A step move still runs on device %1: wait for its end or stop it, then show device %2</source>
        <translation>A step move still runs on device %1: wait for its end or stop it, then show device %2</translation>
    </message>
    <message>
        <source>the port is not open</source>
        <translation>the port is not open</translation>
    </message>
    <message>
        <source>%1 of id %2 is written only while it is the device in view</source>
        <translation>%1 of id %2 is written only while it is the device in view</translation>
    </message>
    <message>
        <source>%1: done; the controller answered after %2 s</source>
        <translation>%1: done; the controller answered after %2 s</translation>
    </message>
    <message>
        <source>Device %1: </source>
        <translation>Device %1: </translation>
    </message>
    <message>
        <source>The controller may have restarted (%1), but reading it again failed: %2</source>
        <translation>The controller may have restarted (%1), but reading it again failed: %2</translation>
    </message>
    <message>
        <source>The controller answers again (%1); what it holds is what StepCom held: nothing shows a restart.</source>
        <translation>The controller answers again (%1); what it holds is what StepCom held: nothing shows a restart.</translation>
    </message>
    <message>
        <source>positions lost</source>
        <translation>positions lost</translation>
    </message>
    <message>
        <source>references lost</source>
        <translation>references lost</translation>
    </message>
    <message>
        <source>changes not saved to flash lost: %1</source>
        <translation>changes not saved to flash lost: %1</translation>
    </message>
    <message>
        <source>The controller restarted (power off?): %1. Seen: %2.</source>
        <translation>The controller restarted (power off?): %1. Seen: %2.</translation>
    </message>
    <message>
        <source>Factory reset: reading it back failed: %1</source>
        <translation>Factory reset: reading it back failed: %1</translation>
    </message>
    <message>
        <source>Factory reset: read back, every value is the factory value.</source>
        <translation>Factory reset: read back, every value is the factory value.</translation>
    </message>
    <message numerus="yes">
        <source>Factory reset: read back; %n value(s) differ from the factory values StepCom knows (another firmware&apos;s defaults?): %1</source>
        <translation>
            <numerusform>Factory reset: read back; %n value differ from the factory values StepCom knows (another firmware&apos;s defaults?): %1</numerusform>
            <numerusform>Factory reset: read back; %n values differ from the factory values StepCom knows (another firmware&apos;s defaults?): %1</numerusform>
        </translation>
    </message>
    <message>
        <source>The controller restarted (power off?): positions lost; references lost. Seen: %1. Reading it again failed (%2): what else it lost is not known.</source>
        <translation>The controller restarted (power off?): positions lost; references lost. Seen: %1. Reading it again failed (%2): what else it lost is not known.</translation>
    </message>
    <message>
        <source>The controller may have restarted (power off?): %1. Every axis reads 0, but only axes that were moving went there: whether they ended there or the controller restarted cannot be told. The references are not known: home again.</source>
        <translation>The controller may have restarted (power off?): %1. Every axis reads 0, but only axes that were moving went there: whether they ended there or the controller restarted cannot be told. The references are not known: home again.</translation>
    </message>
</context>
<context>
    <name>stepcom::DirectionCheck</name>
    <message>
        <source>motor %1 has no direction register in this register map</source>
        <translation>motor %1 has no direction register in this register map</translation>
    </message>
    <message>
        <source>%1 does not have exactly two values: StepCom cannot flip it</source>
        <translation>%1 does not have exactly two values: StepCom cannot flip it</translation>
    </message>
</context>
<context>
    <name>stepcom::EmergencyStop</name>
    <message>
        <source>E-STOP</source>
        <translation>E-STOP</translation>
    </message>
    <message>
        <source>Emergency stop: all motors and outputs off (coil 00042). Key: %1</source>
        <translation>Emergency stop: all motors and outputs off (coil 00042). Key: %1</translation>
    </message>
    <message>
        <source>Nothing to stop: a session log is replayed and no controller is connected. Connect to a controller to use the emergency stop.</source>
        <translation>Nothing to stop: a session log is replayed and no controller is connected. Connect to a controller to use the emergency stop.</translation>
    </message>
    <message>
        <source>Nothing to stop: a profile file is edited and no controller is connected. Connect to a controller to use the emergency stop.</source>
        <translation>Nothing to stop: a profile file is edited and no controller is connected. Connect to a controller to use the emergency stop.</translation>
    </message>
</context>
<context>
    <name>stepcom::EstopConfirmation</name>
    <message>
        <source>E-STOP acknowledged by controller %1 (its answer heard; the register map names no motion state to read back)</source>
        <translation>E-STOP acknowledged by controller %1 (its answer heard; the register map names no motion state to read back)</translation>
    </message>
    <message>
        <source>E-STOP acknowledged by controller %1: both axes stopped</source>
        <translation>E-STOP acknowledged by controller %1: both axes stopped</translation>
    </message>
    <message numerus="yes">
        <source>E-STOP acknowledged by controller %1: %n axis(es) stopped</source>
        <translation>
            <numerusform>E-STOP acknowledged by controller %1: %n axis(es) stopped</numerusform>
            <numerusform>E-STOP acknowledged by controller %1: %n axis(es) stopped</numerusform>
        </translation>
    </message>
    <message>
        <source>Stop the machine by its own E-STOP.</source>
        <translation>Stop the machine by its own E-STOP.</translation>
    </message>
    <message>
        <source>E-STOP not acknowledged by controller %1: motor %2 still running after %3 E-STOPs. %4</source>
        <translation>E-STOP not acknowledged by controller %1: motor %2 still running after %3 E-STOPs. %4</translation>
    </message>
    <message>
        <source>E-STOP not acknowledged by controller %1: a copy of it was heard, but the controller never answered the read of its motion state. %2</source>
        <translation>E-STOP not acknowledged by controller %1: a copy of it was heard, but the controller never answered the read of its motion state. %2</translation>
    </message>
    <message>
        <source>E-STOP not acknowledged by controller %1: only our own echo heard (sent %2 times). %3</source>
        <translation>E-STOP not acknowledged by controller %1: only our own echo heard (sent %2 times). %3</translation>
    </message>
    <message>
        <source>E-STOP sent %1 times into the other master&apos;s line, and controller %2 never answered it. %3</source>
        <translation>E-STOP sent %1 times into the other master&apos;s line, and controller %2 never answered it. %3</translation>
    </message>
</context>
<context>
    <name>stepcom::FaultInjector</name>
    <message>
        <source>&apos;%1&apos; is not a share between 0 and 1 (or 0%-100%)</source>
        <translation>&apos;%1&apos; is not a share between 0 and 1 (or 0%-100%)</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: expected SHARE:NUMBER, e.g. 0.1:500</source>
        <translation>&apos;%1&apos;: expected SHARE:NUMBER, e.g. 0.1:500</translation>
    </message>
</context>
<context>
    <name>stepcom::GamepadJog</name>
    <message>
        <source>the pad went silent</source>
        <translation>the pad went silent</translation>
    </message>
    <message>
        <source>the pad was switched off</source>
        <translation>the pad was switched off</translation>
    </message>
    <message>
        <source>E-STOP on the pad</source>
        <translation>E-STOP on the pad</translation>
    </message>
    <message>
        <source>stop on the pad</source>
        <translation>stop on the pad</translation>
    </message>
    <message>
        <source>the dead-man was let go</source>
        <translation>the dead-man was let go</translation>
    </message>
    <message>
        <source>the stick was let go</source>
        <translation>the stick was let go</translation>
    </message>
    <message>
        <source>the pad was unplugged</source>
        <translation>the pad was unplugged</translation>
    </message>
    <message>
        <source>Pad: %1, the jog stopped</source>
        <translation>Pad: %1, the jog stopped</translation>
    </message>
</context>
<context>
    <name>stepcom::GamepadMapping</name>
    <message>
        <source>unknown key &quot;%1&quot; in the pad&apos;s mapping</source>
        <translation>unknown key &quot;%1&quot; in the pad&apos;s mapping</translation>
    </message>
    <message>
        <source>&quot;%1&quot; names no button of a pad</source>
        <translation>&quot;%1&quot; names no button of a pad</translation>
    </message>
    <message>
        <source>the dead zone must be a number from 0.05 to 0.9</source>
        <translation>the dead zone must be a number from 0.05 to 0.9</translation>
    </message>
    <message>
        <source>&quot;invert_y&quot; must be true or false</source>
        <translation>&quot;invert_y&quot; must be true or false</translation>
    </message>
    <message>
        <source>one button cannot do two things in the pad&apos;s mapping</source>
        <translation>one button cannot do two things in the pad&apos;s mapping</translation>
    </message>
    <message>
        <source>left trigger</source>
        <translation>left trigger</translation>
    </message>
    <message>
        <source>right trigger</source>
        <translation>right trigger</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Back</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>left shoulder</source>
        <translation>left shoulder</translation>
    </message>
    <message>
        <source>right shoulder</source>
        <translation>right shoulder</translation>
    </message>
    <message>
        <source>button %1</source>
        <translation>button %1</translation>
    </message>
</context>
<context>
    <name>stepcom::GamepadPanel</name>
    <message>
        <source>Not changed: %1.</source>
        <translation>Not changed: %1.</translation>
    </message>
    <message>
        <source>Game pads cannot be read: %1</source>
        <translation>Game pads cannot be read: %1</translation>
    </message>
    <message>
        <source>Off: tick it to jog with a game pad.</source>
        <translation>Off: tick it to jog with a game pad.</translation>
    </message>
    <message>
        <source>No pad connected: plug one in or pair it (Bluetooth).</source>
        <translation>No pad connected: plug one in or pair it (Bluetooth).</translation>
    </message>
    <message>
        <source>, wired</source>
        <translation>, wired</translation>
    </message>
    <message>
        <source>, battery about %1 %</source>
        <translation>, battery about %1 %</translation>
    </message>
    <message>
        <source>Connected: %1%2</source>
        <translation>Connected: %1%2</translation>
    </message>
    <message>
        <source>Hold %1 (the dead-man) and move the left stick or the D-pad to jog; %2 stops, %3 is the E-STOP.</source>
        <translation>Hold %1 (the dead-man) and move the left stick or the D-pad to jog; %2 stops, %3 is the E-STOP.</translation>
    </message>
    <message>
        <source>motor %1</source>
        <translation>motor %1</translation>
    </message>
    <message>
        <source>Jogging %1 from the pad.</source>
        <translation>Jogging %1 from the pad.</translation>
    </message>
    <message>
        <source>Home the machine in its homing order? The axes will move to their home switches.</source>
        <translation>Home the machine in its homing order? The axes will move to their home switches.</translation>
    </message>
    <message>
        <source>Home from the pad</source>
        <translation>Home from the pad</translation>
    </message>
    <message>
        <source>Game pad</source>
        <translation>Game pad</translation>
    </message>
    <message>
        <source>&amp;Jog with a game pad</source>
        <translation>&amp;Jog with a game pad</translation>
    </message>
    <message>
        <source>The pad jogs only while its dead-man is held; unplugged or silent, it stops what it jogs.</source>
        <translation>The pad jogs only while its dead-man is held; unplugged or silent, it stops what it jogs.</translation>
    </message>
    <message>
        <source>Dead-man (hold):</source>
        <translation>Dead-man (hold):</translation>
    </message>
    <message>
        <source>Stop:</source>
        <translation>Stop:</translation>
    </message>
    <message>
        <source>Home:</source>
        <translation>Home:</translation>
    </message>
    <message>
        <source>E-STOP:</source>
        <translation>E-STOP:</translation>
    </message>
    <message>
        <source>Dead zone:</source>
        <translation>Dead zone:</translation>
    </message>
</context>
<context>
    <name>stepcom::GuideWindow</name>
    <message>
        <source>The user guide (%1) was not found in %2. It is installed with StepCom; reinstalling the package brings it back.</source>
        <translation>The user guide (%1) was not found in %2. It is installed with StepCom; reinstalling the package brings it back.</translation>
    </message>
    <message>
        <source>The guide has no section &quot;%1&quot;.</source>
        <translation>The guide has no section &quot;%1&quot;.</translation>
    </message>
    <message>
        <source>%1 is not installed with the guide.</source>
        <translation>%1 is not installed with the guide.</translation>
    </message>
    <message>
        <source>User guide</source>
        <translation>User guide</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Back</translation>
    </message>
    <message>
        <source>Back to where you were in the guide</source>
        <translation>Back to where you were in the guide</translation>
    </message>
    <message>
        <source>Go to a section of the guide</source>
        <translation>Go to a section of the guide</translation>
    </message>
    <message>
        <source>Sections</source>
        <translation>Sections</translation>
    </message>
</context>
<context>
    <name>stepcom::HeardEvent</name>
    <message>
        <source> (answered in %1 ms)</source>
        <translation> (answered in %1 ms)</translation>
    </message>
    <message>
        <source>coils %1-%2</source>
        <translation>coils %1-%2</translation>
    </message>
    <message>
        <source>coil %1</source>
        <translation>coil %1</translation>
    </message>
    <message>
        <source>PLC read %1 from id %2: %3%4</source>
        <translation>PLC read %1 from id %2: %3%4</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s)</source>
        <translation>
            <numerusform>%n value</numerusform>
            <numerusform>%n values</numerusform>
        </translation>
    </message>
    <message>
        <source>PLC wrote %1 to id %2%3</source>
        <translation>PLC wrote %1 to id %2%3</translation>
    </message>
    <message>
        <source>PLC sent %1 to id %2%3</source>
        <translation>PLC sent %1 to id %2%3</translation>
    </message>
    <message>
        <source>id %1 refused the PLC&apos;s FC%2 at %3: %4</source>
        <translation>id %1 refused the PLC&apos;s FC%2 at %3: %4</translation>
    </message>
    <message>
        <source>id %1 did not answer the PLC&apos;s FC%2 at %3%4</source>
        <translation>id %1 did not answer the PLC&apos;s FC%2 at %3%4</translation>
    </message>
    <message>
        <source>PLC broadcast FC%1 at %2 to every id: %3</source>
        <translation>PLC broadcast FC%1 at %2 to every id: %3</translation>
    </message>
    <message>
        <source>an answer from id %1 (FC%2) whose request was not heard</source>
        <translation>an answer from id %1 (FC%2) whose request was not heard</translation>
    </message>
</context>
<context>
    <name>stepcom::HomingOrderEditor</name>
    <message>
        <source>%1 is already the %2 in the homing order: a motor homes once. Set the %2 to %3 first.</source>
        <translation>%1 is already the %2 in the homing order: a motor homes once. Set the %2 to %3 first.</translation>
    </message>
    <message>
        <source>no motor</source>
        <translation>no motor</translation>
    </message>
    <message>
        <source>%1, then %2</source>
        <translation>%1, then %2</translation>
    </message>
    <message>
        <source>1st</source>
        <translation>1st</translation>
    </message>
    <message>
        <source>2nd</source>
        <translation>2nd</translation>
    </message>
    <message>
        <source>1st to home:</source>
        <translation>1st to home:</translation>
    </message>
    <message>
        <source>2nd to home:</source>
        <translation>2nd to home:</translation>
    </message>
    <message>
        <source>Not read from the controller yet</source>
        <translation>Not read from the controller yet</translation>
    </message>
    <message>
        <source>The controller holds this order</source>
        <translation>The controller holds this order</translation>
    </message>
    <message>
        <source>Edited, not written yet: apply the order</source>
        <translation>Edited, not written yet: apply the order</translation>
    </message>
    <message>
        <source>Write failed: %1</source>
        <translation>Write failed: %1</translation>
    </message>
    <message>
        <source>Not supported by this controller</source>
        <translation>Not supported by this controller</translation>
    </message>
</context>
<context>
    <name>stepcom::IdAssigner</name>
    <message>
        <source>Connect to the line first (the port the controllers are on, %1 baud, device id %2), then start the assistant.</source>
        <translation>Connect to the line first (the port the controllers are on, %1 baud, device id %2), then start the assistant.</translation>
    </message>
    <message>
        <source>Connect the first controller, alone (a new one answers at id %1, %2 baud), then press Next. It gets id %3.</source>
        <translation>Connect the first controller, alone (a new one answers at id %1, %2 baud), then press Next. It gets id %3.</translation>
    </message>
    <message>
        <source>No free id is left (every id from %1 to 255 is on the list).</source>
        <translation>No free id is left (every id from %1 to 255 is on the list).</translation>
    </message>
    <message>
        <source>Giving the controller at id %1 the id %2…</source>
        <translation>Giving the controller at id %1 the id %2…</translation>
    </message>
    <message>
        <source>Cannot open the port at %1 baud: %2</source>
        <translation>Cannot open the port at %1 baud: %2</translation>
    </message>
    <message>
        <source>Refused: %1. Two controllers with the same id answer at once and garble each other&apos;s answers; nothing was written.</source>
        <translation>Refused: %1. Two controllers with the same id answer at once and garble each other&apos;s answers; nothing was written.</translation>
    </message>
    <message>
        <source>The controller did not get id %1: %2. Check it is the only new controller on the line, then press Next to try again.</source>
        <translation>The controller did not get id %1: %2. Check it is the only new controller on the line, then press Next to try again.</translation>
    </message>
    <message>
        <source>%1. Connect the next controller, alone, then press Next (it gets id %2), or Finish.</source>
        <translation>%1. Connect the next controller, alone, then press Next (it gets id %2), or Finish.</translation>
    </message>
    <message>
        <source>Moving the line to %1 baud…</source>
        <translation>Moving the line to %1 baud…</translation>
    </message>
    <message>
        <source>Asking id %1 at %2 baud</source>
        <translation>Asking id %1 at %2 baud</translation>
    </message>
    <message>
        <source>Finished: no controller was given an id.</source>
        <translation>Finished: no controller was given an id.</translation>
    </message>
    <message>
        <source>Finished: the line is at %1 baud; every controller given an id answers: id %2.</source>
        <translation>Finished: the line is at %1 baud; every controller given an id answers: id %2.</translation>
    </message>
    <message>
        <source>Finished: the line is at %1 baud. Answering: id %2. NOT answering: id %3 — check its power and wiring; it stays on the device list.</source>
        <translation>Finished: the line is at %1 baud. Answering: id %2. NOT answering: id %3 — check its power and wiring; it stays on the device list.</translation>
    </message>
    <message>
        <source>none</source>
        <translation>none</translation>
    </message>
</context>
<context>
    <name>stepcom::IdAssistantDialog</name>
    <message>
        <source>Wait: a controller is being changed. The window closes when it is done.</source>
        <translation>Wait: a controller is being changed. The window closes when it is done.</translation>
    </message>
    <message>
        <source>Assign device ids</source>
        <translation>Assign device ids</translation>
    </message>
    <message>
        <source>Gives each controller of a new line its own id. Every controller leaves the factory with id %1 at %2 baud, so connect them one at a time: connect one, press Next, wait until it answers at its new id, then connect the next. A new id or baud takes effect at once; the assistant follows each controller and checks that it answers at its new id and no longer at id %1.</source>
        <translation>Gives each controller of a new line its own id. Every controller leaves the factory with id %1 at %2 baud, so connect them one at a time: connect one, press Next, wait until it answers at its new id, then connect the next. A new id or baud takes effect at once; the assistant follows each controller and checks that it answers at its new id and no longer at id %1.</translation>
    </message>
    <message>
        <source>Settings</source>
        <translation>Settings</translation>
    </message>
    <message>
        <source>First id to give:</source>
        <translation>First id to give:</translation>
    </message>
    <message>
        <source>Common baud rate:</source>
        <translation>Common baud rate:</translation>
    </message>
    <message>
        <source>Name of the next controller:</source>
        <translation>Name of the next controller:</translation>
    </message>
    <message>
        <source>keep %1 (factory)</source>
        <translation>keep %1 (factory)</translation>
    </message>
    <message>
        <source>New line: start with an empty device list</source>
        <translation>New line: start with an empty device list</translation>
    </message>
    <message>
        <source>optional, e.g. X/Y table</source>
        <translation>optional, e.g. X/Y table</translation>
    </message>
    <message>
        <source>Id</source>
        <translation>Id</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>Next: the controller is connected</source>
        <translation>Next: the controller is connected</translation>
    </message>
    <message>
        <source>Finish</source>
        <translation>Finish</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Close</translation>
    </message>
    <message>
        <source>Press Start. The line&apos;s port is open at %1.</source>
        <translation>Press Start. The line&apos;s port is open at %1.</translation>
    </message>
    <message>
        <source>Connect to the line first (the port the controllers are on, %1 baud, device id %2), then press Start.</source>
        <translation>Connect to the line first (the port the controllers are on, %1 baud, device id %2), then press Start.</translation>
    </message>
    <message>
        <source>Save each id to flash (else lost at power-off)</source>
        <translation>Save each id to flash (else lost at power-off)</translation>
    </message>
    <message>
        <source>Without saving, a controller is back at id %1 and %2 baud after its next power-off.</source>
        <translation>Without saving, a controller is back at id %1 and %2 baud after its next power-off.</translation>
    </message>
</context>
<context>
    <name>stepcom::IdChange</name>
    <message>
        <source>device ids are 1 to 255 (asked: %1 → %2)</source>
        <translation>device ids are 1 to 255 (asked: %1 → %2)</translation>
    </message>
    <message>
        <source>the controller already has id %1</source>
        <translation>the controller already has id %1</translation>
    </message>
    <message>
        <source>the register map has no device.id</source>
        <translation>the register map has no device.id</translation>
    </message>
    <message>
        <source>the register map has no device.baud</source>
        <translation>the register map has no device.baud</translation>
    </message>
    <message>
        <source>not connected: connect to the line first</source>
        <translation>not connected: connect to the line first</translation>
    </message>
    <message>
        <source>Asking the controller at id %1</source>
        <translation>Asking the controller at id %1</translation>
    </message>
    <message>
        <source>garbled answers at id %1: two or more controllers answer there. Connect only the controller that is to get id %2, then try again</source>
        <translation>garbled answers at id %1: two or more controllers answer there. Connect only the controller that is to get id %2, then try again</translation>
    </message>
    <message>
        <source>no controller answers at id %1: %2</source>
        <translation>no controller answers at id %1: %2</translation>
    </message>
    <message>
        <source>Making sure nobody answers at id %1 yet</source>
        <translation>Making sure nobody answers at id %1 yet</translation>
    </message>
    <message>
        <source>id %1 is taken: a controller answers there already. Choose a free id</source>
        <translation>id %1 is taken: a controller answers there already. Choose a free id</translation>
    </message>
    <message>
        <source>Writing id %1 to the controller at id %2</source>
        <translation>Writing id %1 to the controller at id %2</translation>
    </message>
    <message>
        <source>the controller does not answer at id %1: %2</source>
        <translation>the controller does not answer at id %1: %2</translation>
    </message>
    <message>
        <source>Making sure nobody answers at id %1 any more</source>
        <translation>Making sure nobody answers at id %1 any more</translation>
    </message>
    <message>
        <source>the controller answers at id %1 now, but a controller still answers at id %2: more than one controller was connected. Disconnect all but one and try again</source>
        <translation>the controller answers at id %1 now, but a controller still answers at id %2: more than one controller was connected. Disconnect all but one and try again</translation>
    </message>
    <message>
        <source>Writing baud %1 to the controller at id %2</source>
        <translation>Writing baud %1 to the controller at id %2</translation>
    </message>
    <message>
        <source>the controller has id %1, but does not answer at %2 baud: %3</source>
        <translation>the controller has id %1, but does not answer at %2 baud: %3</translation>
    </message>
    <message>
        <source>device id %1 → %2: the controller answers at id %2 at %3 baud</source>
        <translation>device id %1 → %2: the controller answers at id %2 at %3 baud</translation>
    </message>
    <message>
        <source>device id %1 → %2: the controller answers at id %2</source>
        <translation>device id %1 → %2: the controller answers at id %2</translation>
    </message>
    <message>
        <source>the controller answers at id %1, but the register map has no save_to_flash: the id lasts until the power is switched off</source>
        <translation>the controller answers at id %1, but the register map has no save_to_flash: the id lasts until the power is switched off</translation>
    </message>
    <message>
        <source>Saving to flash at id %1</source>
        <translation>Saving to flash at id %1</translation>
    </message>
    <message>
        <source>the controller answers at id %1, but saving to flash failed (%2): the id lasts until the power is switched off; save to flash again</source>
        <translation>the controller answers at id %1, but saving to flash failed (%2): the id lasts until the power is switched off; save to flash again</translation>
    </message>
    <message>
        <source>; saved to flash</source>
        <translation>; saved to flash</translation>
    </message>
    <message>
        <source>; not saved to flash: lost at power-off</source>
        <translation>; not saved to flash: lost at power-off</translation>
    </message>
</context>
<context>
    <name>stepcom::IdList</name>
    <message>
        <source>&apos;%1&apos; is not a device id or a range of ids (e.g. 1,2,3 or 1-3)</source>
        <translation>&apos;%1&apos; is not a device id or a range of ids (e.g. 1,2,3 or 1-3)</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: device ids are 1-255</source>
        <translation>&apos;%1&apos;: device ids are 1-255</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: the range runs backwards</source>
        <translation>&apos;%1&apos;: the range runs backwards</translation>
    </message>
    <message>
        <source>device id %1 is given twice</source>
        <translation>device id %1 is given twice</translation>
    </message>
</context>
<context>
    <name>stepcom::InputTest</name>
    <message>
        <source>positive limit</source>
        <translation>positive limit</translation>
    </message>
    <message>
        <source>negative limit</source>
        <translation>negative limit</translation>
    </message>
    <message>
        <source>home switch</source>
        <translation>home switch</translation>
    </message>
    <message>
        <source>the %1 of motor %2</source>
        <translation>the %1 of motor %2</translation>
    </message>
    <message>
        <source>No input changed while %1 was pressed, and none is configured for it. If the machine has no such switch, skip this step; otherwise check the switch, its wiring and its 24 V supply.</source>
        <translation>No input changed while %1 was pressed, and none is configured for it. If the machine has no such switch, skip this step; otherwise check the switch, its wiring and its 24 V supply.</translation>
    </message>
    <message>
        <source>No input changed while %1 was pressed (configured: %2). Check the switch, its wiring and its 24 V supply (the inputs are active on a 24 V negative signal), then try again.</source>
        <translation>No input changed while %1 was pressed (configured: %2). Check the switch, its wiring and its 24 V supply (the inputs are active on a 24 V negative signal), then try again.</translation>
    </message>
    <message>
        <source>Several inputs changed while %1 was pressed (%2): press only this switch and try again.</source>
        <translation>Several inputs changed while %1 was pressed (%2): press only this switch and try again.</translation>
    </message>
    <message>
        <source>%1 is also configured as the %2 of motor %3</source>
        <translation>%1 is also configured as the %2 of motor %3</translation>
    </message>
    <message>
        <source>%1 answered for %2, as configured.</source>
        <translation>%1 answered for %2, as configured.</translation>
    </message>
    <message>
        <source>%1 answered for %2, which is not configured (none). Proposed: %3.</source>
        <translation>%1 answered for %2, which is not configured (none). Proposed: %3.</translation>
    </message>
    <message>
        <source>%1 answered for %2, but %3 is configured: the wiring and the configuration disagree. Proposed: %4 (or rewire the switch to %3).</source>
        <translation>%1 answered for %2, but %3 is configured: the wiring and the configuration disagree. Proposed: %4 (or rewire the switch to %3).</translation>
    </message>
    <message>
        <source>%1 answered for %2, and this register map cannot name %1 there.</source>
        <translation>%1 answered for %2, and this register map cannot name %1 there.</translation>
    </message>
</context>
<context>
    <name>stepcom::InputsPage</name>
    <message>
        <source>Inputs and limits</source>
        <translation>Inputs and limits</translation>
    </message>
    <message>
        <source>System mode: not known yet.</source>
        <translation>System mode: not known yet.</translation>
    </message>
    <message>
        <source>System mode: %1. The limit and home settings apply.</source>
        <translation>System mode: %1. The limit and home settings apply.</translation>
    </message>
    <message>
        <source>System mode: %1. Motor 1 uses IN1 and IN2 as its limits, IN3 stops it and IN4 starts it.</source>
        <translation>System mode: %1. Motor 1 uses IN1 and IN2 as its limits, IN3 stops it and IN4 starts it.</translation>
    </message>
    <message>
        <source>System mode: %1. The limit settings are ignored: the inputs do what the mode says.</source>
        <translation>System mode: %1. The limit settings are ignored: the inputs do what the mode says.</translation>
    </message>
    <message>
        <source>motor %1 positive limit</source>
        <translation>motor %1 positive limit</translation>
    </message>
    <message>
        <source>motor %1 negative limit</source>
        <translation>motor %1 negative limit</translation>
    </message>
    <message>
        <source>motor %1 home</source>
        <translation>motor %1 home</translation>
    </message>
    <message>
        <source>not used as a limit or home</source>
        <translation>not used as a limit or home</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unknown</translation>
    </message>
    <message>
        <source>on</source>
        <translation>on</translation>
    </message>
    <message>
        <source>off</source>
        <translation>off</translation>
    </message>
    <message>
        <source>Limit and home inputs</source>
        <translation>Limit and home inputs</translation>
    </message>
    <message>
        <source>Wiring check</source>
        <translation>Wiring check</translation>
    </message>
    <message>
        <source>Inputs (live)</source>
        <translation>Inputs (live)</translation>
    </message>
    <message>
        <source>Outputs (live)</source>
        <translation>Outputs (live)</translation>
    </message>
    <message>
        <source>Positive limit</source>
        <translation>Positive limit</translation>
    </message>
    <message>
        <source>Negative limit</source>
        <translation>Negative limit</translation>
    </message>
    <message>
        <source>Home input</source>
        <translation>Home input</translation>
    </message>
    <message>
        <source>Motor &amp;%1:</source>
        <translation>Motor &amp;%1:</translation>
    </message>
    <message>
        <source>Homing runs in reverse until the home input is on, so the home input is usually the negative limit&apos;s input. Inputs are on with a 24 V negative (NPN) signal.</source>
        <translation>Homing runs in reverse until the home input is on, so the home input is usually the negative limit&apos;s input. Inputs are on with a 24 V negative (NPN) signal.</translation>
    </message>
    <message>
        <source>Output %1</source>
        <translation>Output %1</translation>
    </message>
</context>
<context>
    <name>stepcom::InterpolationGeometry</name>
    <message>
        <source>Start and end are the same point: three points cannot describe a full circle. Use the centre mode for a full circle.</source>
        <translation>Start and end are the same point: three points cannot describe a full circle. Use the centre mode for a full circle.</translation>
    </message>
    <message>
        <source>The middle point %1 is the same as the start or the end point: three distinct points are needed.</source>
        <translation>The middle point %1 is the same as the start or the end point: three distinct points are needed.</translation>
    </message>
    <message>
        <source>Start, middle and end are on one straight line: no circle passes through them. Use the line editor for a straight move.</source>
        <translation>Start, middle and end are on one straight line: no circle passes through them. Use the line editor for a straight move.</translation>
    </message>
    <message>
        <source>The start point is the centre: the radius is zero.</source>
        <translation>The start point is the centre: the radius is zero.</translation>
    </message>
    <message>
        <source>The end point is the centre: the radius is zero.</source>
        <translation>The end point is the centre: the radius is zero.</translation>
    </message>
    <message>
        <source>Start and end are not the same distance from the centre: start radius %1, end radius %2, difference %3 (at most %4 allowed).</source>
        <translation>Start and end are not the same distance from the centre: start radius %1, end radius %2, difference %3 (at most %4 allowed).</translation>
    </message>
    <message>
        <source>Start and end are the same point: this is a full circle.</source>
        <translation>Start and end are the same point: this is a full circle.</translation>
    </message>
    <message>
        <source>The arc in the chosen direction does not pass through the middle point: the controller goes the other way round the circle. Change the direction to pass through it.</source>
        <translation>The arc in the chosen direction does not pass through the middle point: the controller goes the other way round the circle. Change the direction to pass through it.</translation>
    </message>
    <message>
        <source>Start and end are the same point %1: the line has no length.</source>
        <translation>Start and end are the same point %1: the line has no length.</translation>
    </message>
</context>
<context>
    <name>stepcom::InterpolationPage</name>
    <message>
        <source>Interpolation</source>
        <translation>Interpolation</translation>
    </message>
    <message>
        <source>Arc</source>
        <translation>Arc</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>Line</translation>
    </message>
    <message>
        <source>Motor 1 (X) [%1]</source>
        <translation>Motor 1 (X) [%1]</translation>
    </message>
    <message>
        <source>Motor 2 (Y) [%1]</source>
        <translation>Motor 2 (Y) [%1]</translation>
    </message>
</context>
<context>
    <name>stepcom::InterpolationPreview</name>
    <message>
        <source>&amp;Fit</source>
        <translation>&amp;Fit</translation>
    </message>
    <message>
        <source>Show the whole path again (or double-click the plot)</source>
        <translation>Show the whole path again (or double-click the plot)</translation>
    </message>
    <message>
        <source>Export P&amp;NG…</source>
        <translation>Export P&amp;NG…</translation>
    </message>
    <message>
        <source>Save the preview as it is shown as a PNG picture</source>
        <translation>Save the preview as it is shown as a PNG picture</translation>
    </message>
    <message>
        <source>Real run</source>
        <translation>Real run</translation>
    </message>
    <message>
        <source>Drag to zoom into a region, wheel or +/- to zoom, middle button or arrow keys to pan, double-click to fit.</source>
        <translation>Drag to zoom into a region, wheel or +/- to zoom, middle button or arrow keys to pan, double-click to fit.</translation>
    </message>
    <message>
        <source>Approach</source>
        <translation>Approach</translation>
    </message>
    <message>
        <source>Arc</source>
        <translation>Arc</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>Line</translation>
    </message>
    <message>
        <source>Invalid</source>
        <translation>Invalid</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>End</source>
        <translation>End</translation>
    </message>
    <message>
        <source>Middle point</source>
        <translation>Middle point</translation>
    </message>
    <message>
        <source>Centre (computed)</source>
        <translation>Centre (computed)</translation>
    </message>
    <message>
        <source>Centre</source>
        <translation>Centre</translation>
    </message>
    <message>
        <source>Invalid: %1</source>
        <translation>Invalid: %1</translation>
    </message>
    <message>
        <source>Dashed: the approach from the current position; both axes start together, each at its own speed, so the last one finishes alone.</source>
        <translation>Dashed: the approach from the current position; both axes start together, each at its own speed, so the last one finishes alone.</translation>
    </message>
    <message>
        <source>Dashed: the approach from the current position (the motors&apos; parameters are not known yet: drawn as equal speeds).</source>
        <translation>Dashed: the approach from the current position (the motors&apos; parameters are not known yet: drawn as equal speeds).</translation>
    </message>
    <message>
        <source>path, arrowheads: direction</source>
        <translation>path, arrowheads: direction</translation>
    </message>
    <message>
        <source>approach</source>
        <translation>approach</translation>
    </message>
    <message>
        <source>real run</source>
        <translation>real run</translation>
    </message>
    <message>
        <source>start</source>
        <translation>start</translation>
    </message>
    <message>
        <source>end</source>
        <translation>end</translation>
    </message>
    <message>
        <source>middle point</source>
        <translation>middle point</translation>
    </message>
    <message>
        <source>centre</source>
        <translation>centre</translation>
    </message>
    <message>
        <source>Export the preview as PNG</source>
        <translation>Export the preview as PNG</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG images (*.png)</translation>
    </message>
    <message>
        <source>Saved “%1”.</source>
        <translation>Saved “%1”.</translation>
    </message>
</context>
<context>
    <name>stepcom::JogController</name>
    <message>
        <source>Motor %1 has stopped now</source>
        <translation>Motor %1 has stopped now</translation>
    </message>
    <message>
        <source>Keyboard jogging is on</source>
        <translation>Keyboard jogging is on</translation>
    </message>
    <message>
        <source>Keyboard jogging is off</source>
        <translation>Keyboard jogging is off</translation>
    </message>
    <message>
        <source>forward</source>
        <translation>forward</translation>
    </message>
    <message>
        <source>reverse</source>
        <translation>reverse</translation>
    </message>
    <message>
        <source>There is no motor %1</source>
        <translation>There is no motor %1</translation>
    </message>
    <message>
        <source>Keyboard jogging is off: motor %1 does not move</source>
        <translation>Keyboard jogging is off: motor %1 does not move</translation>
    </message>
    <message>
        <source>Not connected: motor %1 does not move</source>
        <translation>Not connected: motor %1 does not move</translation>
    </message>
    <message>
        <source>Motor %1 already jogs %2: let go of it first</source>
        <translation>Motor %1 already jogs %2: let go of it first</translation>
    </message>
    <message>
        <source>Motor %1: the last jog command is still on its way; press again</source>
        <translation>Motor %1: the last jog command is still on its way; press again</translation>
    </message>
    <message>
        <source>Motor %1 may still be running after its stop: stop it before jogging</source>
        <translation>Motor %1 may still be running after its stop: stop it before jogging</translation>
    </message>
    <message>
        <source>Motor %1 is moving (a single move, homing or another command): stop it before jogging</source>
        <translation>Motor %1 is moving (a single move, homing or another command): stop it before jogging</translation>
    </message>
    <message>
        <source>Motor %1 has no %2 command in this map</source>
        <translation>Motor %1 has no %2 command in this map</translation>
    </message>
    <message>
        <source>Motor %1: jog %2</source>
        <translation>Motor %1: jog %2</translation>
    </message>
    <message>
        <source>released</source>
        <translation>released</translation>
    </message>
    <message>
        <source>stop button</source>
        <translation>stop button</translation>
    </message>
    <message>
        <source>Motor %1 has no stop command in this map: use the emergency stop</source>
        <translation>Motor %1 has no stop command in this map: use the emergency stop</translation>
    </message>
    <message>
        <source>not connected, the stop could not be sent</source>
        <translation>not connected, the stop could not be sent</translation>
    </message>
    <message>
        <source>Not connected: the stop for motor %1 was not sent</source>
        <translation>Not connected: the stop for motor %1 was not sent</translation>
    </message>
    <message>
        <source>Motor %1: jog %2 failed: %3</source>
        <translation>Motor %1: jog %2 failed: %3</translation>
    </message>
    <message>
        <source>the jog command failed</source>
        <translation>the jog command failed</translation>
    </message>
    <message>
        <source>Motor %1: the stop failed: %2</source>
        <translation>Motor %1: the stop failed: %2</translation>
    </message>
    <message>
        <source>Motor %1 stopped (%2)</source>
        <translation>Motor %1 stopped (%2)</translation>
    </message>
    <message>
        <source>Motor %1 still runs after its stop (%2)! Use the emergency stop, then check the controller.</source>
        <translation>Motor %1 still runs after its stop (%2)! Use the emergency stop, then check the controller.</translation>
    </message>
    <message>
        <source>Motor %1: could not check that it stopped: %2</source>
        <translation>Motor %1: could not check that it stopped: %2</translation>
    </message>
    <message>
        <source>Motor %1 is possibly still running (%2). The stop goes out as soon as the link is back; if needed now, use the machine&apos;s own emergency stop.</source>
        <translation>Motor %1 is possibly still running (%2). The stop goes out as soon as the link is back; if needed now, use the machine&apos;s own emergency stop.</translation>
    </message>
    <message>
        <source>the link was lost while it moved: %1</source>
        <translation>the link was lost while it moved: %1</translation>
    </message>
    <message>
        <source>The link is back: stopping motor %1, which was possibly still running</source>
        <translation>The link is back: stopping motor %1, which was possibly still running</translation>
    </message>
    <message>
        <source>link back</source>
        <translation>link back</translation>
    </message>
    <message>
        <source>Motor %1: jog %2 not done: %3</source>
        <translation>Motor %1: jog %2 not done: %3</translation>
    </message>
    <message>
        <source>E-STOP</source>
        <translation>E-STOP</translation>
    </message>
    <message>
        <source>another hand took over from the pad</source>
        <translation>another hand took over from the pad</translation>
    </message>
    <message>
        <source>Motor %1 was jogged from the pad: it stops; press again to jog it here</source>
        <translation>Motor %1 was jogged from the pad: it stops; press again to jog it here</translation>
    </message>
</context>
<context>
    <name>stepcom::JogPanel</name>
    <message>
        <source>stop button</source>
        <translation>stop button</translation>
    </message>
    <message>
        <source>Not connected.</source>
        <translation>Not connected.</translation>
    </message>
    <message>
        <source>Not read yet: %1.</source>
        <translation>Not read yet: %1.</translation>
    </message>
    <message>
        <source>%1 edited but not written: the controller moves by the values it holds. Write or revert the edit first.</source>
        <translation>%1 edited but not written: the controller moves by the values it holds. Write or revert the edit first.</translation>
    </message>
    <message>
        <source>The motor is moving.</source>
        <translation>The motor is moving.</translation>
    </message>
    <message>
        <source>This controller has no single move.</source>
        <translation>This controller has no single move.</translation>
    </message>
    <message>
        <source>%1, %2, at %3</source>
        <translation>%1, %2, at %3</translation>
    </message>
    <message>
        <source>Jogging forward</source>
        <translation>Jogging forward</translation>
    </message>
    <message>
        <source>Jogging in reverse</source>
        <translation>Jogging in reverse</translation>
    </message>
    <message>
        <source>Stopping…</source>
        <translation>Stopping…</translation>
    </message>
    <message>
        <source>STILL RUNNING after its stop: use the E-STOP</source>
        <translation>STILL RUNNING after its stop: use the E-STOP</translation>
    </message>
    <message>
        <source>Possibly still running: the link was lost; the stop goes out when it is back</source>
        <translation>Possibly still running: the link was lost; the stop goes out when it is back</translation>
    </message>
    <message>
        <source>%1… running</source>
        <translation>%1… running</translation>
    </message>
    <message>
        <source>%1…</source>
        <translation>%1…</translation>
    </message>
    <message>
        <source>Unknown</source>
        <translation>Unknown</translation>
    </message>
    <message>
        <source>Running</source>
        <translation>Running</translation>
    </message>
    <message>
        <source>Idle</source>
        <translation>Idle</translation>
    </message>
    <message>
        <source>Idle — %1</source>
        <translation>Idle — %1</translation>
    </message>
    <message>
        <source>Jogs at %1, the controller&apos;s value, until you apply %2.</source>
        <translation>Jogs at %1, the controller&apos;s value, until you apply %2.</translation>
    </message>
    <message>
        <source>Move once by the distance shown, in the direction and at the speed shown (coil %1)</source>
        <translation>Move once by the distance shown, in the direction and at the speed shown (coil %1)</translation>
    </message>
    <message>
        <source>No home input: runs in reverse until a limit or a stop, without zeroing.</source>
        <translation>No home input: runs in reverse until a limit or a stop, without zeroing.</translation>
    </message>
    <message>
        <source>Reverse until %1, then position 0.</source>
        <translation>Reverse until %1, then position 0.</translation>
    </message>
    <message>
        <source>Motor %1</source>
        <translation>Motor %1</translation>
    </message>
    <message>
        <source>◀ Reverse</source>
        <translation>◀ Reverse</translation>
    </message>
    <message>
        <source>Forward ▶</source>
        <translation>Forward ▶</translation>
    </message>
    <message>
        <source>Hold to run motor %1 in reverse; let go to stop</source>
        <translation>Hold to run motor %1 in reverse; let go to stop</translation>
    </message>
    <message>
        <source>Hold to run motor %1 forward; let go to stop</source>
        <translation>Hold to run motor %1 forward; let go to stop</translation>
    </message>
    <message>
        <source>Stop motor &amp;%1</source>
        <translation>Stop motor &amp;%1</translation>
    </message>
    <message>
        <source>Stop motor %1 at once, whatever started it</source>
        <translation>Stop motor %1 at once, whatever started it</translation>
    </message>
    <message>
        <source>Jog speed:</source>
        <translation>Jog speed:</translation>
    </message>
    <message>
        <source>&amp;Apply speed</source>
        <translation>&amp;Apply speed</translation>
    </message>
    <message>
        <source>Single move:</source>
        <translation>Single move:</translation>
    </message>
    <message>
        <source>&amp;Single move</source>
        <translation>&amp;Single move</translation>
    </message>
    <message>
        <source>Home:</source>
        <translation>Home:</translation>
    </message>
    <message>
        <source>Home &amp;motor %1</source>
        <translation>Home &amp;motor %1</translation>
    </message>
    <message>
        <source>Run motor %1 in reverse to its home input and set its position to 0</source>
        <translation>Run motor %1 in reverse to its home input and set its position to 0</translation>
    </message>
    <message>
        <source>Reference: %1</source>
        <translation>Reference: %1</translation>
    </message>
    <message>
        <source>Write just the jog speed to the controller: the write dialog shows it first, then it is written and read back. The controller takes a new speed even while the motor runs. Other edits wait for &quot;Write changes&quot;.</source>
        <translation>Write just the jog speed to the controller: the write dialog shows it first, then it is written and read back. The controller takes a new speed even while the motor runs. Other edits wait for &quot;Write changes&quot;.</translation>
    </message>
</context>
<context>
    <name>stepcom::LineHub</name>
    <message>
        <source>the line is already open</source>
        <translation>the line is already open</translation>
    </message>
    <message>
        <source>a line needs at least one party, not %1</source>
        <translation>a line needs at least one party, not %1</translation>
    </message>
    <message>
        <source>cannot make a pseudo-terminal: %1</source>
        <translation>cannot make a pseudo-terminal: %1</translation>
    </message>
    <message>
        <source>a line of pseudo-terminals needs Unix</source>
        <translation>a line of pseudo-terminals needs Unix</translation>
    </message>
    <message>
        <source>cannot open %1: %2</source>
        <translation>cannot open %1: %2</translation>
    </message>
    <message>
        <source>no party %1 on the line</source>
        <translation>no party %1 on the line</translation>
    </message>
    <message>
        <source>%1 exists and is not a symlink: not replaced</source>
        <translation>%1 exists and is not a symlink: not replaced</translation>
    </message>
    <message>
        <source>cannot make the symlink %1</source>
        <translation>cannot make the symlink %1</translation>
    </message>
</context>
<context>
    <name>stepcom::LineOptionsBox</name>
    <message>
        <source>Line and adapter</source>
        <translation>Line and adapter</translation>
    </message>
    <message>
        <source>&amp;Answer delay:</source>
        <translation>&amp;Answer delay:</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>T&amp;urnaround:</source>
        <translation>T&amp;urnaround:</translation>
    </message>
    <message>
        <source>Extra silence after an answer before the next request, for converters that need it</source>
        <translation>Extra silence after an answer before the next request, for converters that need it</translation>
    </message>
    <message>
        <source>The adapter &amp;echoes what it sends</source>
        <translation>The adapter &amp;echoes what it sends</translation>
    </message>
    <message>
        <source>How long the controller may take to answer (its manual: 35 ms): the least the timeout is fitted to. Answers are judged by what they say, however soon they come</source>
        <translation>How long the controller may take to answer (its manual: 35 ms): the least the timeout is fitted to. Answers are judged by what they say, however soon they come</translation>
    </message>
    <message>
        <source>For half-duplex USB-RS485 adapters without echo suppression: the request&apos;s own bytes are skipped from the first request on. Without it StepCom finds the echo on the first read</source>
        <translation>For half-duplex USB-RS485 adapters without echo suppression: the request&apos;s own bytes are skipped from the first request on. Without it StepCom finds the echo on the first read</translation>
    </message>
    <message>
        <source>This adapter echoes what it sends: StepCom found the request&apos;s own bytes before the answers and skips them. Remember it for this port?</source>
        <translation>This adapter echoes what it sends: StepCom found the request&apos;s own bytes before the answers and skips them. Remember it for this port?</translation>
    </message>
    <message>
        <source>Remember echo</source>
        <translation>Remember echo</translation>
    </message>
    <message>
        <source>&amp;RS-485 direction:</source>
        <translation>&amp;RS-485 direction:</translation>
    </message>
    <message>
        <source>the adapter switches by itself</source>
        <translation>the adapter switches by itself</translation>
    </message>
    <message>
        <source>the driver&apos;s RS-485 mode (RTS on send)</source>
        <translation>the driver&apos;s RS-485 mode (RTS on send)</translation>
    </message>
    <message>
        <source>StepCom switches RTS</source>
        <translation>StepCom switches RTS</translation>
    </message>
    <message>
        <source>Who switches an RS-485 adapter between sending and receiving. Most adapters do it themselves; some converters need RTS. A driver that refuses is named when connecting, and nothing is sent</source>
        <translation>Who switches an RS-485 adapter between sending and receiving. Most adapters do it themselves; some converters need RTS. A driver that refuses is named when connecting, and nothing is sent</translation>
    </message>
</context>
<context>
    <name>stepcom::LinkHealth</name>
    <message>
        <source>Port closed</source>
        <translation>Port closed</translation>
    </message>
    <message>
        <source>Opening the port…</source>
        <translation>Opening the port…</translation>
    </message>
    <message>
        <source>Port open, waiting for the controller…</source>
        <translation>Port open, waiting for the controller…</translation>
    </message>
    <message>
        <source>Not answering</source>
        <translation>Not answering</translation>
    </message>
    <message>
        <source>Connected</source>
        <translation>Connected</translation>
    </message>
    <message>
        <source>The port is open but no controller answers. Likely causes: another device id (factory: 1), another baud rate (factory: 9600) or parity (factory: none), the RS-485 wires A and B swapped, or the controller has no power. A bus scan tries the ids and baud rates for you.</source>
        <translation>The port is open but no controller answers. Likely causes: another device id (factory: 1), another baud rate (factory: 9600) or parity (factory: none), the RS-485 wires A and B swapped, or the controller has no power. A bus scan tries the ids and baud rates for you.</translation>
    </message>
</context>
<context>
    <name>stepcom::LinkSettings</name>
    <message>
        <source>device id %1 is outside 1-255</source>
        <translation>device id %1 is outside 1-255</translation>
    </message>
    <message>
        <source>timeout %1 ms is outside 20-60000 ms</source>
        <translation>timeout %1 ms is outside 20-60000 ms</translation>
    </message>
    <message>
        <source>retries %1 is outside 0-10</source>
        <translation>retries %1 is outside 0-10</translation>
    </message>
    <message>
        <source>no host given</source>
        <translation>no host given</translation>
    </message>
    <message>
        <source>TCP port %1 is outside 1-65535</source>
        <translation>TCP port %1 is outside 1-65535</translation>
    </message>
    <message>
        <source>no serial port given</source>
        <translation>no serial port given</translation>
    </message>
    <message>
        <source>baud %1 is not one of 4800, 9600, 19200, 38400</source>
        <translation>baud %1 is not one of 4800, 9600, 19200, 38400</translation>
    </message>
    <message>
        <source>stop bits must be 1 or 2</source>
        <translation>stop bits must be 1 or 2</translation>
    </message>
    <message>
        <source>%1:%2 · id %3</source>
        <translation>%1:%2 · id %3</translation>
    </message>
    <message>
        <source>%1 · %2 8%3%4 · id %5</source>
        <translation>%1 · %2 8%3%4 · id %5</translation>
    </message>
    <message>
        <source>%1:%2 (RTU over TCP) · id %3</source>
        <translation>%1:%2 (RTU over TCP) · id %3</translation>
    </message>
    <message>
        <source>answer delay %1 ms is outside 0-1000 ms</source>
        <translation>answer delay %1 ms is outside 0-1000 ms</translation>
    </message>
    <message>
        <source>turnaround %1 ms is outside 0-1000 ms</source>
        <translation>turnaround %1 ms is outside 0-1000 ms</translation>
    </message>
    <message>
        <source>the answer delay (%1 ms) must be shorter than the timeout (%2 ms)</source>
        <translation>the answer delay (%1 ms) must be shorter than the timeout (%2 ms)</translation>
    </message>
    <message>
        <source>RS-485 delays %1/%2 us are outside 0-100000 us</source>
        <translation>RS-485 delays %1/%2 us are outside 0-100000 us</translation>
    </message>
</context>
<context>
    <name>stepcom::LinkStats</name>
    <message>
        <source>; suggested timeout %1 ms (now %2 ms)</source>
        <translation>; suggested timeout %1 ms (now %2 ms)</translation>
    </message>
    <message>
        <source>no answer timed yet</source>
        <translation>no answer timed yet</translation>
    </message>
    <message>
        <source>answers in %1</source>
        <translation>answers in %1</translation>
    </message>
    <message>
        <source>echo not known yet</source>
        <translation>echo not known yet</translation>
    </message>
    <message>
        <source>the adapter echoes</source>
        <translation>the adapter echoes</translation>
    </message>
    <message>
        <source>no echo</source>
        <translation>no echo</translation>
    </message>
    <message>
        <source>timeout %1 ms</source>
        <translation>timeout %1 ms</translation>
    </message>
    <message>
        <source>%1 requests, %2 answers; %3 timeouts, %4 CRC errors, %5 exceptions, %6 stale or foreign answers discarded</source>
        <translation>%1 requests, %2 answers; %3 timeouts, %4 CRC errors, %5 exceptions, %6 stale or foreign answers discarded</translation>
    </message>
    <message>
        <source>line: %1</source>
        <translation>line: %1</translation>
    </message>
</context>
<context>
    <name>stepcom::LinkStatus</name>
    <message>
        <source>Connected (simulator)</source>
        <translation>Connected (simulator)</translation>
    </message>
    <message>
        <source>Connected</source>
        <translation>Connected</translation>
    </message>
    <message>
        <source>Connecting…</source>
        <translation>Connecting…</translation>
    </message>
    <message>
        <source>Disconnected</source>
        <translation>Disconnected</translation>
    </message>
    <message>
        <source>⚠ Not saved to flash</source>
        <translation>⚠ Not saved to flash</translation>
    </message>
    <message>
        <source>Parameters were written but not saved to the controller&apos;s flash: they are lost when it loses power. Use Save to flash.</source>
        <translation>Parameters were written but not saved to the controller&apos;s flash: they are lost when it loses power. Use Save to flash.</translation>
    </message>
    <message>
        <source>Not answering</source>
        <translation>Not answering</translation>
    </message>
    <message>
        <source>Port open, waiting for an answer…</source>
        <translation>Port open, waiting for an answer…</translation>
    </message>
    <message>
        <source>errors: %1 (timeouts %2, CRC %3, exceptions %4, stale answers %5)</source>
        <translation>errors: %1 (timeouts %2, CRC %3, exceptions %4, stale answers %5)</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <source>Stop trying to reconnect; Connect tries again</source>
        <translation>Stop trying to reconnect; Connect tries again</translation>
    </message>
    <message>
        <source>Link lost — reconnecting in %1 s (attempt %2)</source>
        <translation>Link lost — reconnecting in %1 s (attempt %2)</translation>
    </message>
    <message>
        <source>Link lost — reconnecting… (attempt %1)</source>
        <translation>Link lost — reconnecting… (attempt %1)</translation>
    </message>
    <message>
        <source>Line: %1 (at most %2 ms)</source>
        <translation>Line: %1 (at most %2 ms)</translation>
    </message>
    <message>
        <source>%1 transactions/s</source>
        <translation>%1 transactions/s</translation>
    </message>
</context>
<context>
    <name>stepcom::ListenLog</name>
    <message>
        <source>cannot write the session log %1: %2</source>
        <translation>cannot write the session log %1: %2</translation>
    </message>
    <message>
        <source>%1 %2 baud, listening (another master drives the line)</source>
        <translation>%1 %2 baud, listening (another master drives the line)</translation>
    </message>
</context>
<context>
    <name>stepcom::ListenMode</name>
    <message>
        <source>Listening needs the window free: disconnect, and close any profile file or replay first.</source>
        <translation>Listening needs the window free: disconnect, and close any profile file or replay first.</translation>
    </message>
    <message>
        <source>Listening hears a serial line: choose its port on the Connection page.</source>
        <translation>Listening hears a serial line: choose its port on the Connection page.</translation>
    </message>
    <message>
        <source>Cannot listen on %1: %2</source>
        <translation>Cannot listen on %1: %2</translation>
    </message>
    <message>
        <source>Listening ended: the port %1 was lost: %2</source>
        <translation>Listening ended: the port %1 was lost: %2</translation>
    </message>
    <message>
        <source>E-STOP into the other master&apos;s line (try %1)</source>
        <translation>E-STOP into the other master&apos;s line (try %1)</translation>
    </message>
    <message>
        <source>listening on %1 at %2 baud: another master drives the line, StepCom sends nothing</source>
        <translation>listening on %1 at %2 baud: another master drives the line, StepCom sends nothing</translation>
    </message>
    <message>
        <source>heard on %1</source>
        <translation>heard on %1</translation>
    </message>
    <message>
        <source>Stop listening</source>
        <translation>Stop listening</translation>
    </message>
    <message>
        <source>listening ended</source>
        <translation>listening ended</translation>
    </message>
    <message>
        <source>PLC (heard)</source>
        <translation>PLC (heard)</translation>
    </message>
    <message>
        <source>listening on %1</source>
        <translation>listening on %1</translation>
    </message>
    <message>
        <source>E-STOP</source>
        <translation>E-STOP</translation>
    </message>
    <message>
        <source>Send E-STOP</source>
        <translation>Send E-STOP</translation>
    </message>
    <message>
        <source>The E-STOP could not be sent on %1</source>
        <translation>The E-STOP could not be sent on %1</translation>
    </message>
    <message>
        <source>E-STOP sent into a line driven by another master</source>
        <translation>E-STOP sent into a line driven by another master</translation>
    </message>
    <message>
        <source>&lt;b&gt;Listening on %1&lt;/b&gt; — another master drives the line. The values shown are the ones last heard in its traffic with id %2, not read by StepCom; a value never heard is unknown. Nothing is written, jogged or polled; the E-STOP asks first. The other master&apos;s writes (%3):</source>
        <translation>&lt;b&gt;Listening on %1&lt;/b&gt; — another master drives the line. The values shown are the ones last heard in its traffic with id %2, not read by StepCom; a value never heard is unknown. Nothing is written, jogged or polled; the E-STOP asks first. The other master&apos;s writes (%3):</translation>
    </message>
    <message>
        <source>Listen only (another master drives the line)</source>
        <translation>Listen only (another master drives the line)</translation>
    </message>
    <message>
        <source>The other master&apos;s writes</source>
        <translation>The other master&apos;s writes</translation>
    </message>
    <message>
        <source>the controller&apos;s motion state read back after the E-STOP (try %1)</source>
        <translation>the controller&apos;s motion state read back after the E-STOP (try %1)</translation>
    </message>
    <message>
        <source>The adapter on %1 returns what StepCom sends (an echo), but the line&apos;s echo option is off: StepCom&apos;s own E-STOP was not taken for the controller&apos;s answer. Tick &quot;The adapter echoes what it sends&quot; for this line on the Connection page.</source>
        <translation>The adapter on %1 returns what StepCom sends (an echo), but the line&apos;s echo option is off: StepCom&apos;s own E-STOP was not taken for the controller&apos;s answer. Tick &quot;The adapter echoes what it sends&quot; for this line on the Connection page.</translation>
    </message>
    <message>
        <source>Another master drives this line. Send the E-STOP to id %1 into its traffic? It goes in the first silence and again until the controller answers it and its motors are read back stopped.</source>
        <translation>Another master drives this line. Send the E-STOP to id %1 into its traffic? It goes in the first silence and again until the controller answers it and its motors are read back stopped.</translation>
    </message>
</context>
<context>
    <name>stepcom::LostStepResult</name>
    <message>
        <source>kept its steps</source>
        <translation>kept its steps</translation>
    </message>
    <message>
        <source>lost steps</source>
        <translation>lost steps</translation>
    </message>
    <message>
        <source>not known</source>
        <translation>not known</translation>
    </message>
</context>
<context>
    <name>stepcom::MachineActions</name>
    <message>
        <source>Apply profile to &amp;several devices…</source>
        <translation>Apply profile to &amp;several devices…</translation>
    </message>
    <message>
        <source>Compare one profile file with several devices of the line, then write the checked differences to each and verify them</source>
        <translation>Compare one profile file with several devices of the line, then write the checked differences to each and verify them</translation>
    </message>
    <message>
        <source>Save &amp;all devices as profiles…</source>
        <translation>Save &amp;all devices as profiles…</translation>
    </message>
    <message>
        <source>Read every device of the line and save each as a profile file into one folder</source>
        <translation>Read every device of the line and save each as a profile file into one folder</translation>
    </message>
    <message>
        <source>Commissioning report of the &amp;machine…</source>
        <translation>Commissioning report of the &amp;machine…</translation>
    </message>
    <message>
        <source>Read every device of the line, then write one commissioning report of them all</source>
        <translation>Read every device of the line, then write one commissioning report of them all</translation>
    </message>
    <message>
        <source>Apply a profile to several devices</source>
        <translation>Apply a profile to several devices</translation>
    </message>
    <message>
        <source>StepCom profiles (*.json);;All files (*)</source>
        <translation>StepCom profiles (*.json);;All files (*)</translation>
    </message>
    <message>
        <source>The profile cannot be used: nothing was written</source>
        <translation>The profile cannot be used: nothing was written</translation>
    </message>
    <message>
        <source>%1: connect to the line first, and wait for what runs</source>
        <translation>%1: connect to the line first, and wait for what runs</translation>
    </message>
    <message>
        <source>id %1: %2</source>
        <translation>id %1: %2</translation>
    </message>
    <message numerus="yes">
        <source>%1: reading %n device(s)</source>
        <translation>
            <numerusform>%1: reading %n device</numerusform>
            <numerusform>%1: reading %n devices</numerusform>
        </translation>
    </message>
    <message>
        <source>Folder for the profiles of every device</source>
        <translation>Folder for the profiles of every device</translation>
    </message>
    <message>
        <source>Nothing was saved: %1</source>
        <translation>Nothing was saved: %1</translation>
    </message>
    <message>
        <source>Save all devices</source>
        <translation>Save all devices</translation>
    </message>
    <message>
        <source>id %1 was not saved: it could not be read completely</source>
        <translation>id %1 was not saved: it could not be read completely</translation>
    </message>
    <message>
        <source>id %1 saved to %2</source>
        <translation>id %1 saved to %2</translation>
    </message>
    <message>
        <source>id %1 was not saved: %2</source>
        <translation>id %1 was not saved: %2</translation>
    </message>
    <message>
        <source>Commissioning report of the machine</source>
        <translation>Commissioning report of the machine</translation>
    </message>
    <message>
        <source>Notes for the report (machine, place, who commissioned it):</source>
        <translation>Notes for the report (machine, place, who commissioned it):</translation>
    </message>
    <message>
        <source>Save the commissioning report of the machine</source>
        <translation>Save the commissioning report of the machine</translation>
    </message>
    <message>
        <source>PDF (*.pdf);;HTML (*.html)</source>
        <translation>PDF (*.pdf);;HTML (*.html)</translation>
    </message>
    <message>
        <source>Commissioning report</source>
        <translation>Commissioning report</translation>
    </message>
    <message>
        <source>No report: not every device could be read completely</source>
        <translation>No report: not every device could be read completely</translation>
    </message>
    <message numerus="yes">
        <source>Commissioning report of %n device(s) written to %1</source>
        <translation>
            <numerusform>Commissioning report of %n device written to %1</numerusform>
            <numerusform>Commissioning report of %n devices written to %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>stepcom::MachineFile</name>
    <message>
        <source>%1: cannot read the machine file: %2</source>
        <translation>%1: cannot read the machine file: %2</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>not JSON (%1 at offset %2)</source>
        <translation>not JSON (%1 at offset %2)</translation>
    </message>
    <message>
        <source>not a JSON object</source>
        <translation>not a JSON object</translation>
    </message>
    <message>
        <source>format: must be &quot;stepcom-sim-machine&quot;</source>
        <translation>format: must be &quot;stepcom-sim-machine&quot;</translation>
    </message>
    <message>
        <source>version: must be 1</source>
        <translation>version: must be 1</translation>
    </message>
    <message>
        <source>%1: unknown key (the axes are motor1, motor2, ...)</source>
        <translation>%1: unknown key (the axes are motor1, motor2, ...)</translation>
    </message>
    <message>
        <source>%1: must be an object</source>
        <translation>%1: must be an object</translation>
    </message>
</context>
<context>
    <name>stepcom::MachineReport</name>
    <message numerus="yes">
        <source>Commissioning report of a machine: %n controller(s)</source>
        <translation>
            <numerusform>Commissioning report of a machine: %n controller</numerusform>
            <numerusform>Commissioning report of a machine: %n controllers</numerusform>
        </translation>
    </message>
    <message>
        <source>Controller id %1</source>
        <translation>Controller id %1</translation>
    </message>
    <message>
        <source>Controller id %1: %2</source>
        <translation>Controller id %1: %2</translation>
    </message>
    <message>
        <source>Controllers on the line</source>
        <translation>Controllers on the line</translation>
    </message>
    <message>
        <source>Device id</source>
        <translation>Device id</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>Link</translation>
    </message>
    <message>
        <source>Settings fingerprint</source>
        <translation>Settings fingerprint</translation>
    </message>
    <message>
        <source>Date: %1</source>
        <translation>Date: %1</translation>
    </message>
    <message>
        <source>Notes</source>
        <translation>Notes</translation>
    </message>
    <message>
        <source>%1: no controller to report on</source>
        <translation>%1: no controller to report on</translation>
    </message>
    <message>
        <source>%1 -- simulator, not a machine</source>
        <translation>%1 -- simulator, not a machine</translation>
    </message>
    <message>
        <source>built-in simulator -- not a machine</source>
        <translation>built-in simulator -- not a machine</translation>
    </message>
</context>
<context>
    <name>stepcom::MachineStrip</name>
    <message>
        <source>idle</source>
        <translation>idle</translation>
    </message>
    <message>
        <source>running</source>
        <translation>running</translation>
    </message>
    <message>
        <source>at a limit</source>
        <translation>at a limit</translation>
    </message>
    <message>
        <source>Motor %1: %2</source>
        <translation>Motor %1: %2</translation>
    </message>
    <message>
        <source>referenced</source>
        <translation>referenced</translation>
    </message>
    <message>
        <source>not referenced</source>
        <translation>not referenced</translation>
    </message>
    <message>
        <source>Motor %1 position: %2</source>
        <translation>Motor %1 position: %2</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unknown</translation>
    </message>
    <message>
        <source>on</source>
        <translation>on</translation>
    </message>
    <message>
        <source>off</source>
        <translation>off</translation>
    </message>
    <message>
        <source>port closed</source>
        <translation>port closed</translation>
    </message>
    <message>
        <source>asking…</source>
        <translation>asking…</translation>
    </message>
    <message>
        <source>not answering</source>
        <translation>not answering</translation>
    </message>
    <message>
        <source>answering</source>
        <translation>answering</translation>
    </message>
    <message>
        <source>Link: %1</source>
        <translation>Link: %1</translation>
    </message>
    <message>
        <source>Line: %1</source>
        <translation>Line: %1</translation>
    </message>
    <message>
        <source>Device %1</source>
        <translation>Device %1</translation>
    </message>
    <message>
        <source>%1 (id %2)</source>
        <translation>%1 (id %2)</translation>
    </message>
    <message>
        <source>Motor %1</source>
        <translation>Motor %1</translation>
    </message>
    <message>
        <source>Motor %1 position</source>
        <translation>Motor %1 position</translation>
    </message>
    <message>
        <source>IN 1-%1</source>
        <translation>IN 1-%1</translation>
    </message>
    <message>
        <source>OUT 1-%1</source>
        <translation>OUT 1-%1</translation>
    </message>
    <message>
        <source>reference not known</source>
        <translation>reference not known</translation>
    </message>
</context>
<context>
    <name>stepcom::MainWindow</name>
    <message>
        <source>About StepCom</source>
        <translation>About StepCom</translation>
    </message>
    <message>
        <source>&lt;b&gt;StepCom %1&lt;/b&gt;&lt;br&gt;Commissioning tool for 2-axis stepper controllers over Modbus RTU/TCP.&lt;br&gt;GPL-3.0-or-later.</source>
        <translation>&lt;b&gt;StepCom %1&lt;/b&gt;&lt;br&gt;Commissioning tool for 2-axis stepper controllers over Modbus RTU/TCP.&lt;br&gt;GPL-3.0-or-later.</translation>
    </message>
    <message>
        <source>&amp;Read all</source>
        <translation>&amp;Read all</translation>
    </message>
    <message>
        <source>Read every parameter from the controller (%1)</source>
        <translation>Read every parameter from the controller (%1)</translation>
    </message>
    <message>
        <source>&amp;Write changes…</source>
        <translation>&amp;Write changes…</translation>
    </message>
    <message>
        <source>Show the edited values, then write them and verify (%1)</source>
        <translation>Show the edited values, then write them and verify (%1)</translation>
    </message>
    <message>
        <source>Re&amp;vert</source>
        <translation>Re&amp;vert</translation>
    </message>
    <message>
        <source>Drop every edit and show what the controller holds</source>
        <translation>Drop every edit and show what the controller holds</translation>
    </message>
    <message>
        <source>&amp;Save to flash</source>
        <translation>&amp;Save to flash</translation>
    </message>
    <message>
        <source>Save the controller&apos;s parameters to its non-volatile memory (coil 00096)</source>
        <translation>Save the controller&apos;s parameters to its non-volatile memory (coil 00096)</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>&amp;Disconnect</translation>
    </message>
    <message>
        <source>&amp;Emergency stop</source>
        <translation>&amp;Emergency stop</translation>
    </message>
    <message>
        <source>All motors and outputs off, at once (key: %1)</source>
        <translation>All motors and outputs off, at once (key: %1)</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Quit</translation>
    </message>
    <message>
        <source>&amp;About StepCom</source>
        <translation>&amp;About StepCom</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;File</translation>
    </message>
    <message>
        <source>&amp;Device</source>
        <translation>&amp;Device</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;View</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Language</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Help</translation>
    </message>
    <message>
        <source>Main toolbar</source>
        <translation>Main toolbar</translation>
    </message>
    <message>
        <source>Traffic</source>
        <translation>Traffic</translation>
    </message>
    <message>
        <source>Messages</source>
        <translation>Messages</translation>
    </message>
    <message>
        <source>Unwritten changes</source>
        <translation>Unwritten changes</translation>
    </message>
    <message numerus="yes">
        <source>%n edited value(s) were never written to the controller. Close anyway and lose them?</source>
        <translation>
            <numerusform>%n edited value was never written to the controller. Close anyway and lose it?</numerusform>
            <numerusform>%n edited values were never written to the controller. Close anyway and lose them?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n edited value(s) of %1 are not saved in the file. Close anyway and lose them?</source>
        <translation>
            <numerusform>%n edited value of %1 are not saved in the file. Close anyway and lose them?</numerusform>
            <numerusform>%n edited values of %1 are not saved in the file. Close anyway and lose them?</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;User guide</source>
        <translation>&amp;User guide</translation>
    </message>
    <message>
        <source>The user guide at the section about this page (%1)</source>
        <translation>The user guide at the section about this page (%1)</translation>
    </message>
    <message>
        <source>What&apos;s &amp;this?</source>
        <translation>What&apos;s &amp;this?</translation>
    </message>
    <message>
        <source>%1%2 — profile file, no controller</source>
        <translation>%1%2 — profile file, no controller</translation>
    </message>
    <message>
        <source>%1 — replay, no controller</source>
        <translation>%1 — replay, no controller</translation>
    </message>
    <message>
        <source>Create &amp;support bundle…</source>
        <translation>Create &amp;support bundle…</translation>
    </message>
    <message>
        <source>One .zip file with the session logs, the profile and the settings, to send to support</source>
        <translation>One .zip file with the session logs, the profile and the settings, to send to support</translation>
    </message>
    <message>
        <source>Open a file</source>
        <translation>Open a file</translation>
    </message>
    <message>
        <source>Use %1 rpm…</source>
        <translation>Use %1 rpm…</translation>
    </message>
    <message>
        <source>Find a safe speed…</source>
        <translation>Find a safe speed…</translation>
    </message>
    <message>
        <source>Motor %1 lost steps at %2 rpm</source>
        <translation>Motor %1 lost steps at %2 rpm</translation>
    </message>
</context>
<context>
    <name>stepcom::MarginFinder</name>
    <message>
        <source>Motor %1: the acceleration margin at %2 rpm: the lost-step test (%3 cycle(s) of %4 %5 each way) at each acceleration %6 %7, stopping at the first loss</source>
        <translation>Motor %1: the acceleration margin at %2 rpm: the lost-step test (%3 cycle(s) of %4 %5 each way) at each acceleration %6 %7, stopping at the first loss</translation>
    </message>
    <message>
        <source>Motor %1: the speed margin: the lost-step test (%3 cycle(s) of %4 %5 each way) at each speed %6 %7, stopping at the first loss</source>
        <translation>Motor %1: the speed margin: the lost-step test (%3 cycle(s) of %4 %5 each way) at each speed %6 %7, stopping at the first loss</translation>
    </message>
    <message>
        <source>  each test references on the home switch (IN%1) and moves up to %2 %3 past it</source>
        <translation>  each test references on the home switch (IN%1) and moves up to %2 %3 past it</translation>
    </message>
    <message>
        <source>  afterwards: speed %1 rpm and acceleration %2 put back and verified; nothing of the recommendation is written</source>
        <translation>  afterwards: speed %1 rpm and acceleration %2 put back and verified; nothing of the recommendation is written</translation>
    </message>
    <message>
        <source>Motor %1: %2 %3: %4</source>
        <translation>Motor %1: %2 %3: %4</translation>
    </message>
    <message>
        <source>the search must go up: from %1 is above to %2</source>
        <translation>the search must go up: from %1 is above to %2</translation>
    </message>
    <message>
        <source>the step must be at least 1, not %1</source>
        <translation>the step must be at least 1, not %1</translation>
    </message>
    <message>
        <source>%1 values to test: take a larger step (at most 100)</source>
        <translation>%1 values to test: take a larger step (at most 100)</translation>
    </message>
    <message>
        <source>Motor %1: testing %2 %3 (%4 of %5)</source>
        <translation>Motor %1: testing %2 %3 (%4 of %5)</translation>
    </message>
    <message>
        <source>Stopped before anything moved</source>
        <translation>Stopped before anything moved</translation>
    </message>
    <message>
        <source>Motor %1 kept its steps up to %2 %3 and lost them at %4 %3: run at %5 %3 or less</source>
        <translation>Motor %1 kept its steps up to %2 %3 and lost them at %4 %3: run at %5 %3 or less</translation>
    </message>
    <message>
        <source>Motor %1 kept its steps at every value up to %2 %3: run at %4 %3 or less</source>
        <translation>Motor %1 kept its steps at every value up to %2 %3: run at %4 %3 or less</translation>
    </message>
    <message>
        <source>Motor %1 lost steps already at %2 %3, the lowest value tested</source>
        <translation>Motor %1 lost steps already at %2 %3, the lowest value tested</translation>
    </message>
</context>
<context>
    <name>stepcom::MarginPlot</name>
    <message>
        <source>kept its steps</source>
        <translation>kept its steps</translation>
    </message>
    <message>
        <source>lost steps</source>
        <translation>lost steps</translation>
    </message>
    <message>
        <source>recommended</source>
        <translation>recommended</translation>
    </message>
    <message>
        <source>Acceleration (Hz/ms)</source>
        <translation>Acceleration (Hz/ms)</translation>
    </message>
    <message>
        <source>Speed (rpm)</source>
        <translation>Speed (rpm)</translation>
    </message>
    <message>
        <source>Lost (mm)</source>
        <translation>Lost (mm)</translation>
    </message>
</context>
<context>
    <name>stepcom::MessageView</name>
    <message>
        <source>C&amp;lear messages</source>
        <translation>C&amp;lear messages</translation>
    </message>
</context>
<context>
    <name>stepcom::Modbus</name>
    <message>
        <source>illegal function</source>
        <translation>illegal function</translation>
    </message>
    <message>
        <source>illegal data address</source>
        <translation>illegal data address</translation>
    </message>
    <message>
        <source>illegal data value</source>
        <translation>illegal data value</translation>
    </message>
    <message>
        <source>server device failure</source>
        <translation>server device failure</translation>
    </message>
    <message>
        <source>acknowledge</source>
        <translation>acknowledge</translation>
    </message>
    <message>
        <source>server device busy</source>
        <translation>server device busy</translation>
    </message>
    <message>
        <source>exception %1</source>
        <translation>exception %1</translation>
    </message>
</context>
<context>
    <name>stepcom::ModbusLink</name>
    <message>
        <source>no connection to %1 within %2 s</source>
        <translation>no connection to %1 within %2 s</translation>
    </message>
    <message>
        <source>reconnecting</source>
        <translation>reconnecting</translation>
    </message>
    <message>
        <source>serial port %1 does not exist (is the adapter plugged in?)</source>
        <translation>serial port %1 does not exist (is the adapter plugged in?)</translation>
    </message>
    <message>
        <source>no permission to open %1: add your user to the group that owns it (on Debian and Ubuntu: sudo usermod -aG dialout $USER), then log out and in again</source>
        <translation>no permission to open %1: add your user to the group that owns it (on Debian and Ubuntu: sudo usermod -aG dialout $USER), then log out and in again</translation>
    </message>
    <message>
        <source>connecting to %1</source>
        <translation>connecting to %1</translation>
    </message>
    <message>
        <source>cannot open %1</source>
        <translation>cannot open %1</translation>
    </message>
    <message>
        <source>connected to %1</source>
        <translation>connected to %1</translation>
    </message>
    <message>
        <source>connection closed</source>
        <translation>connection closed</translation>
    </message>
    <message>
        <source>the port reported an error</source>
        <translation>the port reported an error</translation>
    </message>
    <message>
        <source>link lost: %1</source>
        <translation>link lost: %1</translation>
    </message>
    <message>
        <source>link closed</source>
        <translation>link closed</translation>
    </message>
    <message>
        <source>disconnected: %1</source>
        <translation>disconnected: %1</translation>
    </message>
    <message>
        <source>%1: not done, %2</source>
        <translation>%1: not done, %2</translation>
    </message>
    <message>
        <source>%1: not connected</source>
        <translation>%1: not connected</translation>
    </message>
    <message>
        <source>%1: cancelled%2</source>
        <translation>%1: cancelled%2</translation>
    </message>
    <message>
        <source>%1: could not send: %2</source>
        <translation>%1: could not send: %2</translation>
    </message>
    <message>
        <source>%1: the controller refused: %2</source>
        <translation>%1: the controller refused: %2</translation>
    </message>
    <message>
        <source>%1: answers had a bad checksum (CRC)</source>
        <translation>%1: answers had a bad checksum (CRC)</translation>
    </message>
    <message>
        <source>%1: no answer within %2 ms</source>
        <translation>%1: no answer within %2 ms</translation>
    </message>
    <message>
        <source> -- the controller may have acted on it</source>
        <translation> -- the controller may have acted on it</translation>
    </message>
    <message>
        <source>the port stopped responding (no answer and no timeout from the driver)</source>
        <translation>the port stopped responding (no answer and no timeout from the driver)</translation>
    </message>
    <message>
        <source>coil %1</source>
        <translation>coil %1</translation>
    </message>
    <message>
        <source>id %1, %2</source>
        <translation>id %1, %2</translation>
    </message>
    <message>
        <source> (discarded: %1)</source>
        <translation> (discarded: %1)</translation>
    </message>
    <message>
        <source>stale/foreign answer discarded: %1</source>
        <translation>stale/foreign answer discarded: %1</translation>
    </message>
    <message>
        <source>the adapter echoes what it sends: the request&apos;s own bytes came back before the answer; they are skipped from now on</source>
        <translation>the adapter echoes what it sends: the request&apos;s own bytes came back before the answer; they are skipped from now on</translation>
    </message>
    <message>
        <source>the adapter does not echo what it sends (the echo option is on): answers are read without skipping a copy</source>
        <translation>the adapter does not echo what it sends (the echo option is on): answers are read without skipping a copy</translation>
    </message>
    <message>
        <source> -- only the request&apos;s own bytes came back (the adapter&apos;s echo): the controller did not answer</source>
        <translation> -- only the request&apos;s own bytes came back (the adapter&apos;s echo): the controller did not answer</translation>
    </message>
    <message>
        <source> -- it answered %1 s ago: busy (writing its flash?), switched off, or a disturbed line</source>
        <translation> -- it answered %1 s ago: busy (writing its flash?), switched off, or a disturbed line</translation>
    </message>
    <message>
        <source> -- check the device id (%1), the host and port, and the converter&apos;s serial settings; the bus scan finds controllers (the window&apos;s Scan bus, or stepcomctl scan)</source>
        <translation> -- check the device id (%1), the host and port, and the converter&apos;s serial settings; the bus scan finds controllers (the window&apos;s Scan bus, or stepcomctl scan)</translation>
    </message>
    <message>
        <source> -- check the device id (%1), the baud rate and parity (%2), the A/B wiring; the bus scan finds controllers (the window&apos;s Scan bus, or stepcomctl scan)</source>
        <translation> -- check the device id (%1), the baud rate and parity (%2), the A/B wiring; the bus scan finds controllers (the window&apos;s Scan bus, or stepcomctl scan)</translation>
    </message>
    <message>
        <source>adapter: %1</source>
        <translation>adapter: %1</translation>
    </message>
</context>
<context>
    <name>stepcom::ModesPage</name>
    <message>
        <source>Normal operation (factory setting): the motors run from commands (this program, the bus); the inputs are the limits and home inputs chosen in the limit settings.</source>
        <translation>Normal operation (factory setting): the motors run from commands (this program, the bus); the inputs are the limits and home inputs chosen in the limit settings.</translation>
    </message>
    <message>
        <source>as set in the limit settings</source>
        <translation>as set in the limit settings</translation>
    </message>
    <message>
        <source>Motor 1 only. A start on IN4 runs it forward to the positive limit (IN1), then in reverse to the negative limit (IN2): one round trip, repeated the round-trip count of times (0 = endless). The speed comes from the on-board or external potentiometer.</source>
        <translation>Motor 1 only. A start on IN4 runs it forward to the positive limit (IN1), then in reverse to the negative limit (IN2): one round trip, repeated the round-trip count of times (0 = endless). The speed comes from the on-board or external potentiometer.</translation>
    </message>
    <message>
        <source>positive limit</source>
        <translation>positive limit</translation>
    </message>
    <message>
        <source>negative limit</source>
        <translation>negative limit</translation>
    </message>
    <message>
        <source>emergency stop</source>
        <translation>emergency stop</translation>
    </message>
    <message>
        <source>start (forward)</source>
        <translation>start (forward)</translation>
    </message>
    <message>
        <source>Motor 1 runs on a short pulse: IN1 starts it (forward the first time), IN2-IN4 stop it and choose the direction of the next start. The limit settings are ignored.</source>
        <translation>Motor 1 runs on a short pulse: IN1 starts it (forward the first time), IN2-IN4 stop it and choose the direction of the next start. The limit settings are ignored.</translation>
    </message>
    <message>
        <source>start (forward the first time)</source>
        <translation>start (forward the first time)</translation>
    </message>
    <message>
        <source>stop; next start keeps the direction</source>
        <translation>stop; next start keeps the direction</translation>
    </message>
    <message>
        <source>stop; next start reverses</source>
        <translation>stop; next start reverses</translation>
    </message>
    <message>
        <source>stop; next start goes forward</source>
        <translation>stop; next start goes forward</translation>
    </message>
    <message>
        <source>Motor 1 runs forward on a pulse on IN1 and in reverse on a pulse on IN2; IN3 and IN4 are its limits. The limit settings are ignored.</source>
        <translation>Motor 1 runs forward on a pulse on IN1 and in reverse on a pulse on IN2; IN3 and IN4 are its limits. The limit settings are ignored.</translation>
    </message>
    <message>
        <source>run forward</source>
        <translation>run forward</translation>
    </message>
    <message>
        <source>run reverse</source>
        <translation>run reverse</translation>
    </message>
    <message>
        <source>positive limit: stops a forward run, only reverse allowed then</source>
        <translation>positive limit: stops a forward run, only reverse allowed then</translation>
    </message>
    <message>
        <source>negative limit: stops a reverse run</source>
        <translation>negative limit: stops a reverse run</translation>
    </message>
    <message>
        <source>Motor 1 runs while IN1 (forward) or IN2 (reverse) is held and stops when it is released; IN3 and IN4 are its limits. The limit settings are ignored.</source>
        <translation>Motor 1 runs while IN1 (forward) or IN2 (reverse) is held and stops when it is released; IN3 and IN4 are its limits. The limit settings are ignored.</translation>
    </message>
    <message>
        <source>held: forward; released: stop</source>
        <translation>held: forward; released: stop</translation>
    </message>
    <message>
        <source>held: reverse; released: stop</source>
        <translation>held: reverse; released: stop</translation>
    </message>
    <message>
        <source>Each pulse on IN1 moves motor 1 forward by its set move distance, each pulse on IN2 in reverse; IN3 and IN4 are its limits. The limit settings are ignored.</source>
        <translation>Each pulse on IN1 moves motor 1 forward by its set move distance, each pulse on IN2 in reverse; IN3 and IN4 are its limits. The limit settings are ignored.</translation>
    </message>
    <message>
        <source>forward by the set distance</source>
        <translation>forward by the set distance</translation>
    </message>
    <message>
        <source>reverse by the set distance</source>
        <translation>reverse by the set distance</translation>
    </message>
    <message>
        <source>Special modes</source>
        <translation>Special modes</translation>
    </message>
    <message>
        <source>IN%1: %2</source>
        <translation>IN%1: %2</translation>
    </message>
    <message>
        <source>Change the system mode</source>
        <translation>Change the system mode</translation>
    </message>
    <message>
        <source>Change the controller to mode %1 “%2”? This changes what the machine&apos;s inputs IN1-IN4 do, at once.</source>
        <translation>Change the controller to mode %1 “%2”? This changes what the machine&apos;s inputs IN1-IN4 do, at once.</translation>
    </message>
    <message>
        <source>Change mode</source>
        <translation>Change mode</translation>
    </message>
    <message>
        <source>The controller&apos;s mode is not known yet.</source>
        <translation>The controller&apos;s mode is not known yet.</translation>
    </message>
    <message>
        <source>The controller runs normally.</source>
        <translation>The controller runs normally.</translation>
    </message>
    <message>
        <source>The controller is in special mode %1.</source>
        <translation>The controller is in special mode %1.</translation>
    </message>
    <message>
        <source>System mode (40300)</source>
        <translation>System mode (40300)</translation>
    </message>
    <message>
        <source>&amp;Mode:</source>
        <translation>&amp;Mode:</translation>
    </message>
    <message>
        <source>What the inputs do in each mode (motor 1; short pulses unless “held”)</source>
        <translation>What the inputs do in each mode (motor 1; short pulses unless “held”)</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Mode</translation>
    </message>
    <message>
        <source>IN1</source>
        <translation>IN1</translation>
    </message>
    <message>
        <source>IN2</source>
        <translation>IN2</translation>
    </message>
    <message>
        <source>IN3</source>
        <translation>IN3</translation>
    </message>
    <message>
        <source>IN4</source>
        <translation>IN4</translation>
    </message>
    <message>
        <source>Limit settings</source>
        <translation>Limit settings</translation>
    </message>
    <message>
        <source>ignored</source>
        <translation>ignored</translation>
    </message>
    <message>
        <source>used</source>
        <translation>used</translation>
    </message>
    <message>
        <source>Round trips (40301)</source>
        <translation>Round trips (40301)</translation>
    </message>
    <message>
        <source>Only used in mode 1 (round trip): how many round trips motor 1 makes after a start; 0 = endless.</source>
        <translation>Only used in mode 1 (round trip): how many round trips motor 1 makes after a start; 0 = endless.</translation>
    </message>
    <message>
        <source>&amp;Write changes…</source>
        <translation>&amp;Write changes…</translation>
    </message>
    <message>
        <source>Modes 2-5 ignore the limit settings: the limit and home inputs set for the motors no longer stop anything. In modes 3-5 only IN3 and IN4 act as limits; in mode 2 nothing does (IN2-IN4 only stop). Wire and test them before using these modes.</source>
        <translation>Modes 2-5 ignore the limit settings: the limit and home inputs set for the motors no longer stop anything. In modes 3-5 only IN3 and IN4 act as limits; in mode 2 nothing does (IN2-IN4 only stop). Wire and test them before using these modes.</translation>
    </message>
    <message>
        <source>The profile file does not set the mode.</source>
        <translation>The profile file does not set the mode.</translation>
    </message>
    <message>
        <source>The profile sets the normal mode.</source>
        <translation>The profile sets the normal mode.</translation>
    </message>
    <message>
        <source>The profile sets special mode %1.</source>
        <translation>The profile sets special mode %1.</translation>
    </message>
    <message>
        <source>Modes 2-5 ignore the limit settings: the limit and home inputs set for the motors no longer stop anything.</source>
        <translation>Modes 2-5 ignore the limit settings: the limit and home inputs set for the motors no longer stop anything.</translation>
    </message>
</context>
<context>
    <name>stepcom::MotionJudge</name>
    <message>
        <source>Motor %1&apos;s positive limit (IN%2) is already ON and %3 drives motor %1 forward: it stops at once.</source>
        <translation>Motor %1&apos;s positive limit (IN%2) is already ON and %3 drives motor %1 forward: it stops at once.</translation>
    </message>
    <message>
        <source>Motor %1&apos;s negative limit (IN%2) is already ON and %3 drives motor %1 in reverse: it stops at once.</source>
        <translation>Motor %1&apos;s negative limit (IN%2) is already ON and %3 drives motor %1 in reverse: it stops at once.</translation>
    </message>
    <message>
        <source>the single move</source>
        <translation>the single move</translation>
    </message>
    <message>
        <source>the return to data zero</source>
        <translation>the return to data zero</translation>
    </message>
    <message>
        <source>the approach to the start point</source>
        <translation>the approach to the start point</translation>
    </message>
    <message>
        <source>the arc</source>
        <translation>the arc</translation>
    </message>
    <message>
        <source>the line</source>
        <translation>the line</translation>
    </message>
    <message>
        <source>Single move of motor %1</source>
        <translation>Single move of motor %1</translation>
    </message>
    <message>
        <source>Homing motor %1</source>
        <translation>Homing motor %1</translation>
    </message>
    <message>
        <source>Homing in order</source>
        <translation>Homing in order</translation>
    </message>
    <message>
        <source>Return to data zero</source>
        <translation>Return to data zero</translation>
    </message>
    <message>
        <source>Arc</source>
        <translation>Arc</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>Line</translation>
    </message>
    <message>
        <source>stop</source>
        <translation>stop</translation>
    </message>
    <message>
        <source>E-STOP</source>
        <translation>E-STOP</translation>
    </message>
    <message>
        <source>link lost</source>
        <translation>link lost</translation>
    </message>
    <message>
        <source>an unknown position</source>
        <translation>an unknown position</translation>
    </message>
    <message>
        <source>motor %1&apos;s positive limit (IN%2) is ON</source>
        <translation>motor %1&apos;s positive limit (IN%2) is ON</translation>
    </message>
    <message>
        <source>motor %1&apos;s negative limit (IN%2) is ON</source>
        <translation>motor %1&apos;s negative limit (IN%2) is ON</translation>
    </message>
    <message>
        <source>%1: done at %2</source>
        <translation>%1: done at %2</translation>
    </message>
    <message>
        <source>%1: referenced at %2</source>
        <translation>%1: referenced at %2</translation>
    </message>
    <message>
        <source>no stop, limit or E-STOP seen</source>
        <translation>no stop, limit or E-STOP seen</translation>
    </message>
    <message>
        <source>%1: stopped at %2, not at the end point %3 (%4)</source>
        <translation>%1: stopped at %2, not at the end point %3 (%4)</translation>
    </message>
    <message>
        <source>%1 interrupted at %2 (%3): not referenced</source>
        <translation>%1 interrupted at %2 (%3): not referenced</translation>
    </message>
    <message>
        <source>%1 interrupted at %2 (%3): motor %4 not referenced</source>
        <translation>%1 interrupted at %2 (%3): motor %4 not referenced</translation>
    </message>
    <message>
        <source>%1 ended without the home input at %2: not referenced</source>
        <translation>%1 ended without the home input at %2: not referenced</translation>
    </message>
    <message>
        <source>%1 ended without the home input at %2: motor %3 not referenced</source>
        <translation>%1 ended without the home input at %2: motor %3 not referenced</translation>
    </message>
    <message>
        <source>the controller restarted</source>
        <translation>the controller restarted</translation>
    </message>
    <message>
        <source>no answer while it moved; the controller may have restarted</source>
        <translation>no answer while it moved; the controller may have restarted</translation>
    </message>
    <message>
        <source>%1: how it ended is not known, last seen at %2 (%3): not referenced</source>
        <translation>%1: how it ended is not known, last seen at %2 (%3): not referenced</translation>
    </message>
</context>
<context>
    <name>stepcom::MotionPage</name>
    <message>
        <source>Coordinates zeroed</source>
        <translation>Coordinates zeroed</translation>
    </message>
    <message>
        <source>Jog and home</source>
        <translation>Jog and home</translation>
    </message>
    <message>
        <source>%1…</source>
        <translation>%1…</translation>
    </message>
    <message>
        <source>%1… motor %2 running</source>
        <translation>%1… motor %2 running</translation>
    </message>
    <message>
        <source>&quot;Home in order&quot; uses the order the controller holds (%1) until you apply the edit.</source>
        <translation>&quot;Home in order&quot; uses the order the controller holds (%1) until you apply the edit.</translation>
    </message>
    <message>
        <source>Homes %1.</source>
        <translation>Homes %1.</translation>
    </message>
    <message>
        <source>&amp;Clear</source>
        <translation>&amp;Clear</translation>
    </message>
    <message>
        <source>Hide this note; the messages dock keeps it</source>
        <translation>Hide this note; the messages dock keeps it</translation>
    </message>
    <message>
        <source>&amp;Keyboard jogging</source>
        <translation>&amp;Keyboard jogging</translation>
    </message>
    <message>
        <source>Off by default. When on, the arrow keys jog while this page is shown and the window has focus</source>
        <translation>Off by default. When on, the arrow keys jog while this page is shown and the window has focus</translation>
    </message>
    <message>
        <source>⌨ KEYBOARD JOGGING ON</source>
        <translation>⌨ KEYBOARD JOGGING ON</translation>
    </message>
    <message>
        <source>Homing</source>
        <translation>Homing</translation>
    </message>
    <message>
        <source>Apply o&amp;rder</source>
        <translation>Apply o&amp;rder</translation>
    </message>
    <message>
        <source>Home &amp;in order</source>
        <translation>Home &amp;in order</translation>
    </message>
    <message>
        <source>&amp;Zero coordinates</source>
        <translation>&amp;Zero coordinates</translation>
    </message>
    <message>
        <source>Make the present positions of all motors 0; nothing moves</source>
        <translation>Make the present positions of all motors 0; nothing moves</translation>
    </message>
    <message>
        <source>Re&amp;turn to data zero</source>
        <translation>Re&amp;turn to data zero</translation>
    </message>
    <message>
        <source>Drive every idle motor back to position 0</source>
        <translation>Drive every idle motor back to position 0</translation>
    </message>
    <message>
        <source>Outputs</source>
        <translation>Outputs</translation>
    </message>
    <message>
        <source>Output 1 o&amp;n</source>
        <translation>Output 1 o&amp;n</translation>
    </message>
    <message>
        <source>O&amp;utput 1 off</source>
        <translation>O&amp;utput 1 off</translation>
    </message>
    <message>
        <source>All out&amp;puts on</source>
        <translation>All out&amp;puts on</translation>
    </message>
    <message>
        <source>All &amp;outputs off</source>
        <translation>All &amp;outputs off</translation>
    </message>
    <message>
        <source>Write just the homing order to the controller: the write dialog shows it first, then it is written and read back</source>
        <translation>Write just the homing order to the controller: the write dialog shows it first, then it is written and read back</translation>
    </message>
    <message>
        <source>Keys: ← → motor 1 reverse/forward, ↓ ↑ motor 2 reverse/forward, Home PgUp End PgDn the diagonals (both motors). Hold to move, let go to stop. Not while typing in a field; leaving the page or the window stops.</source>
        <translation>Keys: ← → motor 1 reverse/forward, ↓ ↑ motor 2 reverse/forward, Home PgUp End PgDn the diagonals (both motors). Hold to move, let go to stop. Not while typing in a field; leaving the page or the window stops.</translation>
    </message>
</context>
<context>
    <name>stepcom::MotorPage</name>
    <message>
        <source>Motor %1</source>
        <translation>Motor %1</translation>
    </message>
    <message>
        <source>Computed from the values shown, including edits not written yet.</source>
        <translation>Computed from the values shown, including edits not written yet.</translation>
    </message>
    <message>
        <source>Computed from the values shown.</source>
        <translation>Computed from the values shown.</translation>
    </message>
    <message>
        <source>Motor %1 parameters</source>
        <translation>Motor %1 parameters</translation>
    </message>
    <message>
        <source>Derived values</source>
        <translation>Derived values</translation>
    </message>
    <message>
        <source>Motion</source>
        <translation>Motion</translation>
    </message>
    <message>
        <source>&amp;Stop motor %1</source>
        <translation>&amp;Stop motor %1</translation>
    </message>
    <message>
        <source>Stops the motor at once, without a ramp. The E-STOP under every page stops everything.</source>
        <translation>Stops the motor at once, without a ramp. The E-STOP under every page stops everything.</translation>
    </message>
</context>
<context>
    <name>stepcom::MoveHere</name>
    <message>
        <source>not connected</source>
        <translation>not connected</translation>
    </message>
    <message>
        <source>a move is under way</source>
        <translation>a move is under way</translation>
    </message>
    <message>
        <source>motor %1 is not referenced: home it first</source>
        <translation>motor %1 is not referenced: home it first</translation>
    </message>
    <message>
        <source>the position of motor %1 is not known</source>
        <translation>the position of motor %1 is not known</translation>
    </message>
    <message>
        <source>Move here (%1, %2)</source>
        <translation>Move here (%1, %2)</translation>
    </message>
    <message>
        <source>Move here: %1</source>
        <translation>Move here: %1</translation>
    </message>
    <message>
        <source>Not moved: %1.</source>
        <translation>Not moved: %1.</translation>
    </message>
    <message>
        <source>motor %1: %2 → %3 %4 (%5%6 %4)</source>
        <translation>motor %1: %2 → %3 %4 (%5%6 %4)</translation>
    </message>
    <message>
        <source>Move both axes to (%1, %2)?
%3</source>
        <translation>Move both axes to (%1, %2)?
%3</translation>
    </message>
    <message>
        <source>Move here</source>
        <translation>Move here</translation>
    </message>
    <message>
        <source>Not moved.</source>
        <translation>Not moved.</translation>
    </message>
    <message>
        <source>Not moved: %1</source>
        <translation>Not moved: %1</translation>
    </message>
    <message>
        <source>Moving to (%1, %2)…</source>
        <translation>Moving to (%1, %2)…</translation>
    </message>
</context>
<context>
    <name>stepcom::OfflineActions</name>
    <message>
        <source>&amp;New profile from factory values</source>
        <translation>&amp;New profile from factory values</translation>
    </message>
    <message>
        <source>Edit a new profile, starting from the factory values, without a controller</source>
        <translation>Edit a new profile, starting from the factory values, without a controller</translation>
    </message>
    <message>
        <source>Save p&amp;rofile file</source>
        <translation>Save p&amp;rofile file</translation>
    </message>
    <message>
        <source>Save the profile being edited to its file (no controller is written)</source>
        <translation>Save the profile being edited to its file (no controller is written)</translation>
    </message>
    <message>
        <source>Save profile file &amp;as…</source>
        <translation>Save profile file &amp;as…</translation>
    </message>
    <message>
        <source>Save the profile being edited to another file</source>
        <translation>Save the profile being edited to another file</translation>
    </message>
    <message>
        <source>&amp;Close profile file</source>
        <translation>&amp;Close profile file</translation>
    </message>
    <message>
        <source>Stop editing the profile file</source>
        <translation>Stop editing the profile file</translation>
    </message>
    <message>
        <source>&amp;Compare profiles…</source>
        <translation>&amp;Compare profiles…</translation>
    </message>
    <message>
        <source>Compare two profile files row by row; no controller is needed</source>
        <translation>Compare two profile files row by row; no controller is needed</translation>
    </message>
    <message>
        <source>Report from a &amp;profile…</source>
        <translation>Report from a &amp;profile…</translation>
    </message>
    <message>
        <source>The commissioning report made from a profile file (or the file being edited), not from a controller</source>
        <translation>The commissioning report made from a profile file (or the file being edited), not from a controller</translation>
    </message>
    <message>
        <source>Unsaved edits</source>
        <translation>Unsaved edits</translation>
    </message>
    <message numerus="yes">
        <source>%n edited value(s) of %1 are not saved in the file.</source>
        <translation>
            <numerusform>%n edited value of %1 are not saved in the file.</numerusform>
            <numerusform>%n edited values of %1 are not saved in the file.</numerusform>
        </translation>
    </message>
    <message>
        <source>The profile cannot be edited</source>
        <translation>The profile cannot be edited</translation>
    </message>
    <message>
        <source>Editing the profile file %1 without a controller</source>
        <translation>Editing the profile file %1 without a controller</translation>
    </message>
    <message>
        <source>New profile</source>
        <translation>New profile</translation>
    </message>
    <message>
        <source>Editing a new profile with the factory values; nothing is written to a controller</source>
        <translation>Editing a new profile with the factory values; nothing is written to a controller</translation>
    </message>
    <message>
        <source>Save profile</source>
        <translation>Save profile</translation>
    </message>
    <message>
        <source>Saved the profile to %1 (no controller was written)</source>
        <translation>Saved the profile to %1 (no controller was written)</translation>
    </message>
    <message numerus="yes">
        <source>The file lacked %n setting(s); they were saved with their factory values: %1</source>
        <translation>
            <numerusform>The file lacked %n setting; they were saved with their factory values: %1</numerusform>
            <numerusform>The file lacked %n settings; they were saved with their factory values: %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Save profile file as</source>
        <translation>Save profile file as</translation>
    </message>
    <message>
        <source>StepCom profiles (*.json)</source>
        <translation>StepCom profiles (*.json)</translation>
    </message>
    <message>
        <source>Compare profiles: choose two files</source>
        <translation>Compare profiles: choose two files</translation>
    </message>
    <message>
        <source>StepCom profiles (*.json);;All files (*)</source>
        <translation>StepCom profiles (*.json);;All files (*)</translation>
    </message>
    <message>
        <source>Compare profiles</source>
        <translation>Compare profiles</translation>
    </message>
    <message numerus="yes">
        <source>Choose exactly two profile files (%n chosen).</source>
        <translation>
            <numerusform>Choose exactly two profile files (%n chosen).</numerusform>
            <numerusform>Choose exactly two profile files (%n chosen).</numerusform>
        </translation>
    </message>
    <message>
        <source>The profiles cannot be compared</source>
        <translation>The profiles cannot be compared</translation>
    </message>
    <message>
        <source>Compared %1 with %2</source>
        <translation>Compared %1 with %2</translation>
    </message>
    <message>
        <source>Report from a profile: choose the profile</source>
        <translation>Report from a profile: choose the profile</translation>
    </message>
    <message>
        <source>Report from a profile</source>
        <translation>Report from a profile</translation>
    </message>
    <message>
        <source>Notes for the report (empty: the profile&apos;s own notes):</source>
        <translation>Notes for the report (empty: the profile&apos;s own notes):</translation>
    </message>
    <message>
        <source>Save the report made from the profile</source>
        <translation>Save the report made from the profile</translation>
    </message>
    <message>
        <source>PDF (*.pdf);;HTML (*.html)</source>
        <translation>PDF (*.pdf);;HTML (*.html)</translation>
    </message>
    <message>
        <source>Report made from the profile file %1 (no controller was read) written to %2</source>
        <translation>Report made from the profile file %1 (no controller was read) written to %2</translation>
    </message>
    <message>
        <source>(with edits not saved in the file)</source>
        <translation>(with edits not saved in the file)</translation>
    </message>
    <message>
        <source>new profile</source>
        <translation>new profile</translation>
    </message>
    <message numerus="yes">
        <source>Profile applied: %n value(s) written and verified</source>
        <translation>
            <numerusform>Profile applied: %n value written and verified</numerusform>
            <numerusform>Profile applied: %n values written and verified</numerusform>
        </translation>
    </message>
    <message>
        <source>Connected: the values of %1 are compared with the controller&apos;s; nothing is written until you apply checked rows</source>
        <translation>Connected: the values of %1 are compared with the controller&apos;s; nothing is written until you apply checked rows</translation>
    </message>
    <message numerus="yes">
        <source>%n edit(s) of %1 were never saved: they are in the comparison, not in the file</source>
        <translation>
            <numerusform>%n edit of %1 were never saved: they are in the comparison, not in the file</numerusform>
            <numerusform>%n edits of %1 were never saved: they are in the comparison, not in the file</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>stepcom::OfflineBanner</name>
    <message>
        <source>Editing the profile file %1 — no controller. Nothing here moves or writes a controller; connect to compare the values with one and apply them.</source>
        <translation>Editing the profile file %1 — no controller. Nothing here moves or writes a controller; connect to compare the values with one and apply them.</translation>
    </message>
    <message>
        <source>Edits not saved yet.</source>
        <translation>Edits not saved yet.</translation>
    </message>
    <message>
        <source>This map cannot take everything the file holds (saved again, the file keeps it; settings it lacks are filled with factory values when you save):</source>
        <translation>This map cannot take everything the file holds (saved again, the file keeps it; settings it lacks are filled with factory values when you save):</translation>
    </message>
</context>
<context>
    <name>stepcom::PageSidebar</name>
    <message numerus="yes">
        <source>%n edit(s) not written</source>
        <translation>
            <numerusform>%n edit not written</numerusform>
            <numerusform>%n edits not written</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 of %2 steps passed</source>
        <translation>%1 of %2 steps passed</translation>
    </message>
    <message>
        <source>steps passed not known</source>
        <translation>steps passed not known</translation>
    </message>
    <message>
        <source>needs a controller that answers (%1)</source>
        <translation>needs a controller that answers (%1)</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Connect</translation>
    </message>
    <message>
        <source>Set up</source>
        <translation>Set up</translation>
    </message>
    <message>
        <source>Move and run</source>
        <translation>Move and run</translation>
    </message>
    <message>
        <source>Check, save and report</source>
        <translation>Check, save and report</translation>
    </message>
    <message>
        <source>More pages above</source>
        <translation>More pages above</translation>
    </message>
    <message>
        <source>More pages below</source>
        <translation>More pages below</translation>
    </message>
</context>
<context>
    <name>stepcom::Parameter</name>
    <message>
        <source>%1: %2 is not one of %3</source>
        <translation>%1: %2 is not one of %3</translation>
    </message>
    <message>
        <source>%1: %2 is out of range (%3)</source>
        <translation>%1: %2 is out of range (%3)</translation>
    </message>
    <message>
        <source>%1: no value given</source>
        <translation>%1: no value given</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number</source>
        <translation>%1: &apos;%2&apos; is not a number</translation>
    </message>
    <message numerus="yes">
        <source>%1: &apos;%2&apos; has more than %n decimal(s)</source>
        <translation>
            <numerusform>%1: &apos;%2&apos; has more than %n decimal</numerusform>
            <numerusform>%1: &apos;%2&apos; has more than %n decimals</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is far too large</source>
        <translation>%1: &apos;%2&apos; is far too large</translation>
    </message>
    <message>
        <source>%1: not a finite number</source>
        <translation>%1: not a finite number</translation>
    </message>
    <message>
        <source>%1: %2 is far too large</source>
        <translation>%1: %2 is far too large</translation>
    </message>
    <message numerus="yes">
        <source>%1: %2 has more than %n decimal(s)</source>
        <translation>
            <numerusform>%1: %2 has more than %n decimal</numerusform>
            <numerusform>%1: %2 has more than %n decimals</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not one of %3</source>
        <translation>%1: &apos;%2&apos; is not one of %3</translation>
    </message>
</context>
<context>
    <name>stepcom::ParameterField</name>
    <message>
        <source>Not read from the controller yet</source>
        <translation>Not read from the controller yet</translation>
    </message>
    <message>
        <source>The controller holds this value</source>
        <translation>The controller holds this value</translation>
    </message>
    <message>
        <source>Edited, not written yet (the controller holds %1)</source>
        <translation>Edited, not written yet (the controller holds %1)</translation>
    </message>
    <message>
        <source>Edited, not written yet</source>
        <translation>Edited, not written yet</translation>
    </message>
    <message>
        <source>Write failed: %1</source>
        <translation>Write failed: %1</translation>
    </message>
    <message>
        <source>The profile file lacks this value</source>
        <translation>The profile file lacks this value</translation>
    </message>
    <message>
        <source>The profile file holds this value</source>
        <translation>The profile file holds this value</translation>
    </message>
    <message>
        <source>Edited, not saved yet (the file holds %1)</source>
        <translation>Edited, not saved yet (the file holds %1)</translation>
    </message>
    <message>
        <source>Edited, not saved yet</source>
        <translation>Edited, not saved yet</translation>
    </message>
    <message>
        <source>Not supported by this controller: it refuses to read this register</source>
        <translation>Not supported by this controller: it refuses to read this register</translation>
    </message>
</context>
<context>
    <name>stepcom::ParameterStore</name>
    <message>
        <source>unknown parameter %1</source>
        <translation>unknown parameter %1</translation>
    </message>
    <message>
        <source>%1 is read-only</source>
        <translation>%1 is read-only</translation>
    </message>
    <message>
        <source>the controller holds %1 instead</source>
        <translation>the controller holds %1 instead</translation>
    </message>
    <message>
        <source>not written: an earlier write failed</source>
        <translation>not written: an earlier write failed</translation>
    </message>
    <message>
        <source>%1 is not supported by this controller</source>
        <translation>%1 is not supported by this controller</translation>
    </message>
</context>
<context>
    <name>stepcom::PathEditor</name>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>%1 min %2 s</source>
        <translation>%1 min %2 s</translation>
    </message>
    <message>
        <source>Radius</source>
        <translation>Radius</translation>
    </message>
    <message>
        <source>Centre</source>
        <translation>Centre</translation>
    </message>
    <message>
        <source>Start / end radius</source>
        <translation>Start / end radius</translation>
    </message>
    <message>
        <source>Sweep</source>
        <translation>Sweep</translation>
    </message>
    <message>
        <source>Path length</source>
        <translation>Path length</translation>
    </message>
    <message>
        <source>Path speed</source>
        <translation>Path speed</translation>
    </message>
    <message>
        <source>Estimated time</source>
        <translation>Estimated time</translation>
    </message>
    <message>
        <source>Not connected.</source>
        <translation>Not connected.</translation>
    </message>
    <message>
        <source>A value is being typed: press Enter to keep it, then write it.</source>
        <translation>A value is being typed: press Enter to keep it, then write it.</translation>
    </message>
    <message>
        <source>Changes not written yet: write them first, so the controller runs what the preview shows.</source>
        <translation>Changes not written yet: write them first, so the controller runs what the preview shows.</translation>
    </message>
    <message>
        <source>Not read from the controller yet.</source>
        <translation>Not read from the controller yet.</translation>
    </message>
    <message>
        <source>The geometry is invalid: %1</source>
        <translation>The geometry is invalid: %1</translation>
    </message>
    <message>
        <source>Arc interpolation is off (40182): choose “Motors 1+2 interpolate” and write it.</source>
        <translation>Arc interpolation is off (40182): choose “Motors 1+2 interpolate” and write it.</translation>
    </message>
    <message>
        <source>Line interpolation is off (40202): choose “Motors 1+2 interpolate” and write it.</source>
        <translation>Line interpolation is off (40202): choose “Motors 1+2 interpolate” and write it.</translation>
    </message>
    <message>
        <source>A motor is moving: wait until it stops, or stop it.</source>
        <translation>A motor is moving: wait until it stops, or stop it.</translation>
    </message>
    <message>
        <source>Starting…</source>
        <translation>Starting…</translation>
    </message>
    <message>
        <source> — computed from the three points</source>
        <translation> — computed from the three points</translation>
    </message>
    <message>
        <source>%1 / %2 (difference %3, at most %4)</source>
        <translation>%1 / %2 (difference %3, at most %4)</translation>
    </message>
    <message>
        <source>%1° (full circle)</source>
        <translation>%1° (full circle)</translation>
    </message>
    <message>
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <source>%1 rpm = %2 %3/s</source>
        <translation>%1 rpm = %2 %3/s</translation>
    </message>
    <message>
        <source>%1 (approach %2 + path %3)</source>
        <translation>%1 (approach %2 + path %3)</translation>
    </message>
    <message>
        <source>Ready: Start runs the path shown, as written.</source>
        <translation>Ready: Start runs the path shown, as written.</translation>
    </message>
    <message>
        <source>Arc parameters</source>
        <translation>Arc parameters</translation>
    </message>
    <message>
        <source>Line parameters</source>
        <translation>Line parameters</translation>
    </message>
    <message>
        <source>What the controller will do</source>
        <translation>What the controller will do</translation>
    </message>
    <message>
        <source>Run the arc</source>
        <translation>Run the arc</translation>
    </message>
    <message>
        <source>Run the line</source>
        <translation>Run the line</translation>
    </message>
    <message>
        <source>Estimated time: the approach from where the axes are now (each axis on its own at its own speed) plus the path, driven at the set speed as motor 1 revolutions per minute with motor 1&apos;s start frequency, acceleration and pitch, as the simulator runs it. A real controller may differ.</source>
        <translation>Estimated time: the approach from where the axes are now (each axis on its own at its own speed) plus the path, driven at the set speed as motor 1 revolutions per minute with motor 1&apos;s start frequency, acceleration and pitch, as the simulator runs it. A real controller may differ.</translation>
    </message>
    <message>
        <source>&amp;Write changes…</source>
        <translation>&amp;Write changes…</translation>
    </message>
    <message>
        <source>Write this editor&apos;s changes to the controller and read them back</source>
        <translation>Write this editor&apos;s changes to the controller and read them back</translation>
    </message>
    <message>
        <source>Start arc</source>
        <translation>Start arc</translation>
    </message>
    <message>
        <source>Start line</source>
        <translation>Start line</translation>
    </message>
    <message>
        <source>Coil 00100: each axis first moves to the start point on its own, then both follow the arc</source>
        <translation>Coil 00100: each axis first moves to the start point on its own, then both follow the arc</translation>
    </message>
    <message>
        <source>Coil 00102: each axis first moves to the start point on its own, then both follow the line</source>
        <translation>Coil 00102: each axis first moves to the start point on its own, then both follow the line</translation>
    </message>
    <message>
        <source>Stop arc</source>
        <translation>Stop arc</translation>
    </message>
    <message>
        <source>Stop line</source>
        <translation>Stop line</translation>
    </message>
    <message>
        <source>Coil 00101, sent ahead of everything queued</source>
        <translation>Coil 00101, sent ahead of everything queued</translation>
    </message>
    <message>
        <source>Coil 00103, sent ahead of everything queued</source>
        <translation>Coil 00103, sent ahead of everything queued</translation>
    </message>
    <message>
        <source>⚠ Start is possible, but: %1</source>
        <translation>⚠ Start is possible, but: %1</translation>
    </message>
    <message>
        <source>%1: running…</source>
        <translation>%1: running…</translation>
    </message>
    <message>
        <source>Last run: %1</source>
        <translation>Last run: %1</translation>
    </message>
    <message>
        <source>Times as the simulator runs the path; a real controller may differ.</source>
        <translation>Times as the simulator runs the path; a real controller may differ.</translation>
    </message>
</context>
<context>
    <name>stepcom::PendantActions</name>
    <message>
        <source>A replay serves no pendant: close the session log first</source>
        <translation>A replay serves no pendant: close the session log first</translation>
    </message>
    <message>
        <source>A profile file edited without a controller serves no pendant</source>
        <translation>A profile file edited without a controller serves no pendant</translation>
    </message>
    <message>
        <source>A phone or tablet as the pendant: watch, E-STOP, and jog when you allow it</source>
        <translation>A phone or tablet as the pendant: watch, E-STOP, and jog when you allow it</translation>
    </message>
    <message>
        <source>Pendant: jogging from %1</source>
        <translation>Pendant: jogging from %1</translation>
    </message>
    <message>
        <source>Pendant: on, no phone yet</source>
        <translation>Pendant: on, no phone yet</translation>
    </message>
    <message>
        <source>Pendant: 1 phone watching</source>
        <translation>Pendant: 1 phone watching</translation>
    </message>
    <message>
        <source>Pendant: %1 phones watching</source>
        <translation>Pendant: %1 phones watching</translation>
    </message>
    <message>
        <source>Pendant…</source>
        <translation>Pendant…</translation>
    </message>
    <message>
        <source>Listening beside another master serves no pendant: stop listening first</source>
        <translation>Listening beside another master serves no pendant: stop listening first</translation>
    </message>
</context>
<context>
    <name>stepcom::PendantControl</name>
    <message>
        <source>no hold from the pendant for %1 ms</source>
        <translation>no hold from the pendant for %1 ms</translation>
    </message>
    <message>
        <source>the pendant stopped</source>
        <translation>the pendant stopped</translation>
    </message>
    <message>
        <source>jogging from the pendant was turned off</source>
        <translation>jogging from the pendant was turned off</translation>
    </message>
    <message>
        <source>Jogging from the pendant is not allowed in the window</source>
        <translation>Jogging from the pendant is not allowed in the window</translation>
    </message>
    <message>
        <source>another phone took control</source>
        <translation>another phone took control</translation>
    </message>
    <message>
        <source>the phone gave up control</source>
        <translation>the phone gave up control</translation>
    </message>
    <message>
        <source>the window took control back</source>
        <translation>the window took control back</translation>
    </message>
    <message>
        <source>the phone&apos;s connection closed</source>
        <translation>the phone&apos;s connection closed</translation>
    </message>
    <message>
        <source>Take control first</source>
        <translation>Take control first</translation>
    </message>
    <message>
        <source>Another phone holds control</source>
        <translation>Another phone holds control</translation>
    </message>
    <message>
        <source>There is no motor %1</source>
        <translation>There is no motor %1</translation>
    </message>
    <message>
        <source>Motor %1 does not move</source>
        <translation>Motor %1 does not move</translation>
    </message>
    <message>
        <source>A step must be greater than 0</source>
        <translation>A step must be greater than 0</translation>
    </message>
</context>
<context>
    <name>stepcom::PendantDialog</name>
    <message>
        <source>Pendant</source>
        <translation>Pendant</translation>
    </message>
    <message>
        <source>A phone or tablet on the same network becomes the pendant: scan the code or type the address into its browser. It shows the positions, inputs and outputs and has an E-STOP; it jogs only while you allow it here.</source>
        <translation>A phone or tablet on the same network becomes the pendant: scan the code or type the address into its browser. It shows the positions, inputs and outputs and has an E-STOP; it jogs only while you allow it here.</translation>
    </message>
    <message>
        <source>&amp;Port:</source>
        <translation>&amp;Port:</translation>
    </message>
    <message>
        <source>Allow jogging from the pendant</source>
        <translation>Allow jogging from the pendant</translation>
    </message>
    <message>
        <source>Take control back</source>
        <translation>Take control back</translation>
    </message>
    <message>
        <source>Phones connected:</source>
        <translation>Phones connected:</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Address</translation>
    </message>
    <message>
        <source>Browser</source>
        <translation>Browser</translation>
    </message>
    <message>
        <source>Since</source>
        <translation>Since</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>&amp;Disconnect</translation>
    </message>
    <message>
        <source>The phone is no safety device: the machine&apos;s own E-STOP circuit stays the safety.</source>
        <translation>The phone is no safety device: the machine&apos;s own E-STOP circuit stays the safety.</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Close</translation>
    </message>
    <message>
        <source>QR code of the pendant&apos;s address</source>
        <translation>QR code of the pendant&apos;s address</translation>
    </message>
    <message>
        <source>&amp;Stop the pendant</source>
        <translation>&amp;Stop the pendant</translation>
    </message>
    <message>
        <source>&amp;Start the pendant</source>
        <translation>&amp;Start the pendant</translation>
    </message>
    <message>
        <source>The pendant is off.</source>
        <translation>The pendant is off.</translation>
    </message>
    <message>
        <source>Pendant address: %1</source>
        <translation>Pendant address: %1</translation>
    </message>
    <message>
        <source>Control: %1</source>
        <translation>Control: %1</translation>
    </message>
    <message>
        <source>Control: nobody (the window)</source>
        <translation>Control: nobody (the window)</translation>
    </message>
</context>
<context>
    <name>stepcom::PendantPage</name>
    <message>
        <source>StepCom pendant</source>
        <translation>StepCom pendant</translation>
    </message>
    <message>
        <source>Motor 1 position</source>
        <translation>Motor 1 position</translation>
    </message>
    <message>
        <source>Motor 2 position</source>
        <translation>Motor 2 position</translation>
    </message>
    <message>
        <source>Motor 1 forward</source>
        <translation>Motor 1 forward</translation>
    </message>
    <message>
        <source>Motor 1 reverse</source>
        <translation>Motor 1 reverse</translation>
    </message>
    <message>
        <source>Motor 2 forward</source>
        <translation>Motor 2 forward</translation>
    </message>
    <message>
        <source>Motor 2 reverse</source>
        <translation>Motor 2 reverse</translation>
    </message>
    <message>
        <source>Motor 1</source>
        <translation>Motor 1</translation>
    </message>
    <message>
        <source>Motor 2</source>
        <translation>Motor 2</translation>
    </message>
    <message>
        <source>E-STOP</source>
        <translation>E-STOP</translation>
    </message>
    <message>
        <source>Take control</source>
        <translation>Take control</translation>
    </message>
    <message>
        <source>Give up control</source>
        <translation>Give up control</translation>
    </message>
    <message>
        <source>You hold control: hold a button to jog</source>
        <translation>You hold control: hold a button to jog</translation>
    </message>
    <message>
        <source>%1 holds control</source>
        <translation>%1 holds control</translation>
    </message>
    <message>
        <source>Watching only: jogging is not allowed in the window</source>
        <translation>Watching only: jogging is not allowed in the window</translation>
    </message>
    <message>
        <source>Jogging is allowed: take control to jog</source>
        <translation>Jogging is allowed: take control to jog</translation>
    </message>
    <message>
        <source>idle</source>
        <translation>idle</translation>
    </message>
    <message>
        <source>running</source>
        <translation>running</translation>
    </message>
    <message>
        <source>at a limit</source>
        <translation>at a limit</translation>
    </message>
    <message>
        <source>referenced</source>
        <translation>referenced</translation>
    </message>
    <message>
        <source>not referenced</source>
        <translation>not referenced</translation>
    </message>
    <message>
        <source>Inputs</source>
        <translation>Inputs</translation>
    </message>
    <message>
        <source>Outputs</source>
        <translation>Outputs</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>Link</translation>
    </message>
    <message>
        <source>port closed</source>
        <translation>port closed</translation>
    </message>
    <message>
        <source>asking…</source>
        <translation>asking…</translation>
    </message>
    <message>
        <source>not answering</source>
        <translation>not answering</translation>
    </message>
    <message>
        <source>answering</source>
        <translation>answering</translation>
    </message>
    <message>
        <source>Device %1</source>
        <translation>Device %1</translation>
    </message>
    <message>
        <source>%1 (id %2)</source>
        <translation>%1 (id %2)</translation>
    </message>
    <message>
        <source>no data</source>
        <translation>no data</translation>
    </message>
    <message>
        <source>updated %1 s ago</source>
        <translation>updated %1 s ago</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Step</translation>
    </message>
    <message>
        <source>Motor %1 step −</source>
        <translation>Motor %1 step −</translation>
    </message>
    <message>
        <source>Motor %1 step +</source>
        <translation>Motor %1 step +</translation>
    </message>
    <message>
        <source>The pendant was stopped in StepCom</source>
        <translation>The pendant was stopped in StepCom</translation>
    </message>
    <message>
        <source>StepCom disconnected this phone</source>
        <translation>StepCom disconnected this phone</translation>
    </message>
    <message>
        <source>Connection lost: reload the page</source>
        <translation>Connection lost: reload the page</translation>
    </message>
    <message>
        <source>This phone is no safety device: the machine&apos;s own E-STOP is.</source>
        <translation>This phone is no safety device: the machine&apos;s own E-STOP is.</translation>
    </message>
</context>
<context>
    <name>stepcom::PendantServer</name>
    <message>
        <source>&apos;%1&apos; is not [ADDRESS:]PORT: the port must be a number from 0 to 65535</source>
        <translation>&apos;%1&apos; is not [ADDRESS:]PORT: the port must be a number from 0 to 65535</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not [ADDRESS:]PORT: &apos;%2&apos; is not an IP address</source>
        <translation>&apos;%1&apos; is not [ADDRESS:]PORT: &apos;%2&apos; is not an IP address</translation>
    </message>
    <message>
        <source>The pendant cannot listen on %1 port %2: %3</source>
        <translation>The pendant cannot listen on %1 port %2: %3</translation>
    </message>
</context>
<context>
    <name>stepcom::PlotPage</name>
    <message>
        <source>Plots</source>
        <translation>Plots</translation>
    </message>
    <message>
        <source>Cannot write the picture “%1”.</source>
        <translation>Cannot write the picture “%1”.</translation>
    </message>
    <message>
        <source>Record status to CSV</source>
        <translation>Record status to CSV</translation>
    </message>
    <message>
        <source>Export plots as PNG</source>
        <translation>Export plots as PNG</translation>
    </message>
    <message>
        <source>Export visible samples as CSV</source>
        <translation>Export visible samples as CSV</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG images (*.png)</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV files (*.csv)</translation>
    </message>
    <message>
        <source>Saved “%1”.</source>
        <translation>Saved “%1”.</translation>
    </message>
    <message numerus="yes">
        <source>Recording to “%1”: %n sample(s)</source>
        <translation>
            <numerusform>Recording to “%1”: %n sample</numerusform>
            <numerusform>Recording to “%1”: %n samples</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Not recording. Samples of the last %n minute(s) are kept for the plots and exports.</source>
        <translation>
            <numerusform>Not recording. Samples of the last %n minute are kept for the plots and exports.</numerusform>
            <numerusform>Not recording. Samples of the last %n minutes are kept for the plots and exports.</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Resume</source>
        <translation>&amp;Resume</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pause</translation>
    </message>
    <message>
        <source>Freeze the plots; samples are still taken and recorded</source>
        <translation>Freeze the plots; samples are still taken and recorded</translation>
    </message>
    <message>
        <source>&amp;Fit</source>
        <translation>&amp;Fit</translation>
    </message>
    <message>
        <source>Show all of the data (or double-click a plot). Drag to zoom into a region, wheel to zoom, middle button to pan.</source>
        <translation>Show all of the data (or double-click a plot). Drag to zoom into a region, wheel to zoom, middle button to pan.</translation>
    </message>
    <message>
        <source>&amp;Clear path</source>
        <translation>&amp;Clear path</translation>
    </message>
    <message>
        <source>Start the tool path trace again from here</source>
        <translation>Start the tool path trace again from here</translation>
    </message>
    <message>
        <source>&amp;Window:</source>
        <translation>&amp;Window:</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>How many seconds the position plot shows</source>
        <translation>How many seconds the position plot shows</translation>
    </message>
    <message>
        <source>Export P&amp;NG…</source>
        <translation>Export P&amp;NG…</translation>
    </message>
    <message>
        <source>Save both plots as they are shown as a PNG picture</source>
        <translation>Save both plots as they are shown as a PNG picture</translation>
    </message>
    <message>
        <source>Export CS&amp;V…</source>
        <translation>Export CS&amp;V…</translation>
    </message>
    <message>
        <source>Save the samples in the visible time range as CSV</source>
        <translation>Save the samples in the visible time range as CSV</translation>
    </message>
    <message>
        <source>&amp;Stop recording</source>
        <translation>&amp;Stop recording</translation>
    </message>
    <message>
        <source>&amp;Record CSV…</source>
        <translation>&amp;Record CSV…</translation>
    </message>
    <message>
        <source>Write every status sample to a CSV file as it arrives</source>
        <translation>Write every status sample to a CSV file as it arrives</translation>
    </message>
    <message>
        <source>Motor %1</source>
        <translation>Motor %1</translation>
    </message>
    <message>
        <source>Motor %1 (%2)</source>
        <translation>Motor %1 (%2)</translation>
    </message>
    <message>
        <source>Tool path</source>
        <translation>Tool path</translation>
    </message>
</context>
<context>
    <name>stepcom::Poller</name>
    <message numerus="yes">
        <source>… %n in all</source>
        <translation>
            <numerusform>… %n in all</numerusform>
            <numerusform>… %n in all</numerusform>
        </translation>
    </message>
    <message>
        <source>poll %1/%2 (%3)</source>
        <translation>poll %1/%2 (%3)</translation>
    </message>
</context>
<context>
    <name>stepcom::PortHolders</name>
    <message>
        <source>process %1</source>
        <translation>process %1</translation>
    </message>
    <message>
        <source>%1, process %2</source>
        <translation>%1, process %2</translation>
    </message>
    <message>
        <source>%1 is in use by another program</source>
        <translation>%1 is in use by another program</translation>
    </message>
    <message>
        <source>%1 is in use by another program (%2)</source>
        <translation>%1 is in use by another program (%2)</translation>
    </message>
</context>
<context>
    <name>stepcom::PortSetup</name>
    <message>
        <source>its driver</source>
        <translation>its driver</translation>
    </message>
    <message>
        <source>not on this system</source>
        <translation>not on this system</translation>
    </message>
    <message>
        <source>%1: the driver (%2) refused to switch RTS (%3); StepCom cannot drive the RS-485 direction by RTS here: try --rs485 auto with an adapter that switches by itself</source>
        <translation>%1: the driver (%2) refused to switch RTS (%3); StepCom cannot drive the RS-485 direction by RTS here: try --rs485 auto with an adapter that switches by itself</translation>
    </message>
    <message>
        <source>%1: the driver (%2) has no kernel RS-485 mode (%3): try --rs485 rts (StepCom switches RTS itself) or --rs485 auto (the adapter switches by itself)</source>
        <translation>%1: the driver (%2) has no kernel RS-485 mode (%3): try --rs485 rts (StepCom switches RTS itself) or --rs485 auto (the adapter switches by itself)</translation>
    </message>
    <message>
        <source>%1: RS-485 direction modes need Linux: use --rs485 auto</source>
        <translation>%1: RS-485 direction modes need Linux: use --rs485 auto</translation>
    </message>
</context>
<context>
    <name>stepcom::PortSurvey</name>
    <message>
        <source>lock file %1</source>
        <translation>lock file %1</translation>
    </message>
    <message>
        <source>has it open</source>
        <translation>has it open</translation>
    </message>
    <message>
        <source>whether another program holds it is not known here</source>
        <translation>whether another program holds it is not known here</translation>
    </message>
    <message>
        <source>free, as far as this user can see</source>
        <translation>free, as far as this user can see</translation>
    </message>
    <message>
        <source>free</source>
        <translation>free</translation>
    </message>
    <message>
        <source>%1 (pid %2, %3)</source>
        <translation>%1 (pid %2, %3)</translation>
    </message>
    <message>
        <source>a program</source>
        <translation>a program</translation>
    </message>
    <message>
        <source>held by %1</source>
        <translation>held by %1</translation>
    </message>
</context>
<context>
    <name>stepcom::PositionPlot</name>
    <message>
        <source>Cannot write the picture “%1”.</source>
        <translation>Cannot write the picture “%1”.</translation>
    </message>
    <message>
        <source>Motor %1</source>
        <translation>Motor %1</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Position</translation>
    </message>
    <message>
        <source>Position (%1)</source>
        <translation>Position (%1)</translation>
    </message>
    <message>
        <source>Drag to zoom into a region, wheel or +/- to zoom, middle button or arrow keys to pan, double-click or Home to fit. Zooming pauses the view.</source>
        <translation>Drag to zoom into a region, wheel or +/- to zoom, middle button or arrow keys to pan, double-click or Home to fit. Zooming pauses the view.</translation>
    </message>
    <message>
        <source>Time (s), 0 = %1</source>
        <translation>Time (s), 0 = %1</translation>
    </message>
</context>
<context>
    <name>stepcom::ProfileActions</name>
    <message>
        <source>&amp;Open profile…</source>
        <translation>&amp;Open profile…</translation>
    </message>
    <message>
        <source>Compare a profile file with the controller; nothing is written until you apply checked rows</source>
        <translation>Compare a profile file with the controller; nothing is written until you apply checked rows</translation>
    </message>
    <message>
        <source>Save profile from &amp;device…</source>
        <translation>Save profile from &amp;device…</translation>
    </message>
    <message>
        <source>Read every parameter, then save them as a profile file</source>
        <translation>Read every parameter, then save them as a profile file</translation>
    </message>
    <message>
        <source>Save profile from &amp;edited values…</source>
        <translation>Save profile from &amp;edited values…</translation>
    </message>
    <message>
        <source>Save the values the pages show (edits included) as a profile file</source>
        <translation>Save the values the pages show (edits included) as a profile file</translation>
    </message>
    <message>
        <source>Commissioning &amp;report…</source>
        <translation>Commissioning &amp;report…</translation>
    </message>
    <message>
        <source>Read everything, then write the commissioning sheet as PDF or HTML</source>
        <translation>Read everything, then write the commissioning sheet as PDF or HTML</translation>
    </message>
    <message>
        <source>Recent &amp;profiles</source>
        <translation>Recent &amp;profiles</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(none)</translation>
    </message>
    <message>
        <source>Nothing was written to the controller.</source>
        <translation>Nothing was written to the controller.</translation>
    </message>
    <message>
        <source>Open profile</source>
        <translation>Open profile</translation>
    </message>
    <message>
        <source>StepCom profiles (*.json);;All files (*)</source>
        <translation>StepCom profiles (*.json);;All files (*)</translation>
    </message>
    <message>
        <source>Save profile from the device</source>
        <translation>Save profile from the device</translation>
    </message>
    <message>
        <source>Save profile from the edited values</source>
        <translation>Save profile from the edited values</translation>
    </message>
    <message>
        <source>StepCom profiles (*.json)</source>
        <translation>StepCom profiles (*.json)</translation>
    </message>
    <message>
        <source>Commissioning report</source>
        <translation>Commissioning report</translation>
    </message>
    <message>
        <source>Notes for the report (machine, place, who commissioned it):</source>
        <translation>Notes for the report (machine, place, who commissioned it):</translation>
    </message>
    <message>
        <source>Save the commissioning report</source>
        <translation>Save the commissioning report</translation>
    </message>
    <message>
        <source>PDF (*.pdf);;HTML (*.html)</source>
        <translation>PDF (*.pdf);;HTML (*.html)</translation>
    </message>
    <message>
        <source>The profile cannot be used</source>
        <translation>The profile cannot be used</translation>
    </message>
    <message numerus="yes">
        <source>Profile applied: %n value(s) written and verified</source>
        <translation>
            <numerusform>Profile applied: %n value written and verified</numerusform>
            <numerusform>Profile applied: %n values written and verified</numerusform>
        </translation>
    </message>
    <message>
        <source>Opened profile %1</source>
        <translation>Opened profile %1</translation>
    </message>
    <message>
        <source>Save profile</source>
        <translation>Save profile</translation>
    </message>
    <message>
        <source>Connect to a controller first.</source>
        <translation>Connect to a controller first.</translation>
    </message>
    <message>
        <source>Nothing was saved: the controller could not be read completely.</source>
        <translation>Nothing was saved: the controller could not be read completely.</translation>
    </message>
    <message numerus="yes">
        <source>Saved the controller&apos;s %n parameter(s) to %1</source>
        <translation>
            <numerusform>Saved the controller&apos;s %n parameter to %1</numerusform>
            <numerusform>Saved the controller&apos;s %n parameters to %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) are not known yet (read all first): %1</source>
        <translation>
            <numerusform>%n value is not known yet (read all first): %1</numerusform>
            <numerusform>%n values are not known yet (read all first): %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Saved %n value(s) as shown (edits included) to %1</source>
        <translation>
            <numerusform>Saved %n value as shown (edits included) to %1</numerusform>
            <numerusform>Saved %n values as shown (edits included) to %1</numerusform>
        </translation>
    </message>
    <message>
        <source>No report: the controller could not be read completely.</source>
        <translation>No report: the controller could not be read completely.</translation>
    </message>
    <message>
        <source>Commissioning report written to %1</source>
        <translation>Commissioning report written to %1</translation>
    </message>
    <message>
        <source>Connected: compare a profile file with the controller (nothing is written until you apply checked rows). Without a controller: edit the file on the pages</source>
        <translation>Connected: compare a profile file with the controller (nothing is written until you apply checked rows). Without a controller: edit the file on the pages</translation>
    </message>
    <message>
        <source>The backup cannot be used</source>
        <translation>The backup cannot be used</translation>
    </message>
    <message>
        <source>Opened backup %1</source>
        <translation>Opened backup %1</translation>
    </message>
    <message>
        <source>&amp;Backups…</source>
        <translation>&amp;Backups…</translation>
    </message>
    <message>
        <source>The controller&apos;s settings saved before each apply, factory reset, save to flash and id or baud change</source>
        <translation>The controller&apos;s settings saved before each apply, factory reset, save to flash and id or baud change</translation>
    </message>
    <message>
        <source>The software travel limits of %1 are in use now</source>
        <translation>The software travel limits of %1 are in use now</translation>
    </message>
</context>
<context>
    <name>stepcom::ProfileApply</name>
    <message>
        <source>not done: E-STOP</source>
        <translation>not done: E-STOP</translation>
    </message>
    <message>
        <source>stopped by the E-STOP: nothing more was sent for this profile</source>
        <translation>stopped by the E-STOP: nothing more was sent for this profile</translation>
    </message>
    <message>
        <source>the link was closed</source>
        <translation>the link was closed</translation>
    </message>
    <message>
        <source>the controller could not be read</source>
        <translation>the controller could not be read</translation>
    </message>
    <message>
        <source>the link was lost</source>
        <translation>the link was lost</translation>
    </message>
    <message>
        <source>the controller could not be read: %1</source>
        <translation>the controller could not be read: %1</translation>
    </message>
    <message>
        <source>the profile holds no value</source>
        <translation>the profile holds no value</translation>
    </message>
    <message>
        <source>this controller does not have it</source>
        <translation>this controller does not have it</translation>
    </message>
    <message>
        <source>the device id and baud are applied only to the device in view, when asked for</source>
        <translation>the device id and baud are applied only to the device in view, when asked for</translation>
    </message>
    <message>
        <source>it is read-only</source>
        <translation>it is read-only</translation>
    </message>
    <message>
        <source>not a setting of this register map</source>
        <translation>not a setting of this register map</translation>
    </message>
    <message>
        <source>the session ended</source>
        <translation>the session ended</translation>
    </message>
    <message>
        <source>the link was lost before it was sent</source>
        <translation>the link was lost before it was sent</translation>
    </message>
    <message>
        <source>stopped by the E-STOP while writing</source>
        <translation>stopped by the E-STOP while writing</translation>
    </message>
    <message>
        <source>refused by the controller</source>
        <translation>refused by the controller</translation>
    </message>
    <message>
        <source>not sent: an earlier write failed</source>
        <translation>not sent: an earlier write failed</translation>
    </message>
    <message>
        <source>sent without a good answer</source>
        <translation>sent without a good answer</translation>
    </message>
    <message>
        <source>the controller restarted during the apply: what it held then was lost unless saved to flash</source>
        <translation>the controller restarted during the apply: what it held then was lost unless saved to flash</translation>
    </message>
    <message>
        <source>the controller restarted</source>
        <translation>the controller restarted</translation>
    </message>
    <message>
        <source>the controller holds %1</source>
        <translation>the controller holds %1</translation>
    </message>
    <message>
        <source>this map has no save_to_flash command</source>
        <translation>this map has no save_to_flash command</translation>
    </message>
    <message>
        <source>saved to flash only on the device in view</source>
        <translation>saved to flash only on the device in view</translation>
    </message>
    <message>
        <source>the link went away during the apply (%1)</source>
        <translation>the link went away during the apply (%1)</translation>
    </message>
</context>
<context>
    <name>stepcom::ProfileApplyResult</name>
    <message>
        <source>%1: already %2</source>
        <translation>%1: already %2</translation>
    </message>
    <message>
        <source>%1: %2 (written, verified)</source>
        <translation>%1: %2 (written, verified)</translation>
    </message>
    <message>
        <source>%1: wrote %2, the controller holds %3</source>
        <translation>%1: wrote %2, the controller holds %3</translation>
    </message>
    <message>
        <source>%1: wrote %2, could not read it back</source>
        <translation>%1: wrote %2, could not read it back</translation>
    </message>
    <message>
        <source>%1: %2 refused: %3</source>
        <translation>%1: %2 refused: %3</translation>
    </message>
    <message>
        <source>%1: not written (%2)</source>
        <translation>%1: not written (%2)</translation>
    </message>
    <message>
        <source>%1: not known whether %2 was written (%3)</source>
        <translation>%1: not known whether %2 was written (%3)</translation>
    </message>
    <message>
        <source>%1: wrote %2, then the controller held %3 again (%4)</source>
        <translation>%1: wrote %2, then the controller held %3 again (%4)</translation>
    </message>
</context>
<context>
    <name>stepcom::ProfileCompareDialog</name>
    <message>
        <source>Saved to flash: the controller keeps these values after power-off.</source>
        <translation>Saved to flash: the controller keeps these values after power-off.</translation>
    </message>
    <message>
        <source>Saving to flash failed (see Messages).</source>
        <translation>Saving to flash failed (see Messages).</translation>
    </message>
    <message>
        <source>The controller forgets these values at power-off unless they are saved to flash.</source>
        <translation>The controller forgets these values at power-off unless they are saved to flash.</translation>
    </message>
    <message>
        <source>Motor %1 · %2</source>
        <translation>Motor %1 · %2</translation>
    </message>
    <message>
        <source>link setting</source>
        <translation>link setting</translation>
    </message>
    <message>
        <source>The profile does not hold this value</source>
        <translation>The profile does not hold this value</translation>
    </message>
    <message>
        <source>The controller&apos;s values are not known yet: connect, and they are read.</source>
        <translation>The controller&apos;s values are not known yet: connect, and they are read.</translation>
    </message>
    <message>
        <source>The controller holds every value of the profile.</source>
        <translation>The controller holds every value of the profile.</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) differ; %1 checked to be written.</source>
        <translation>
            <numerusform>%n value differs; %1 checked to be written.</numerusform>
            <numerusform>%n values differ; %1 checked to be written.</numerusform>
        </translation>
    </message>
    <message>
        <source>Connect to a controller to apply</source>
        <translation>Connect to a controller to apply</translation>
    </message>
    <message numerus="yes">
        <source>Writing %n value(s), then reading them back…</source>
        <translation>
            <numerusform>Writing %n value, then reading it back…</numerusform>
            <numerusform>Writing %n values, then reading them back…</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Wrote and verified %n value(s).</source>
        <translation>
            <numerusform>Wrote and verified %n value.</numerusform>
            <numerusform>Wrote and verified %n values.</numerusform>
        </translation>
    </message>
    <message>
        <source>Problems:</source>
        <translation>Problems:</translation>
    </message>
    <message>
        <source>Profile %1 — compare and apply</source>
        <translation>Profile %1 — compare and apply</translation>
    </message>
    <message>
        <source>Profile &quot;%1&quot; from %2</source>
        <translation>Profile &quot;%1&quot; from %2</translation>
    </message>
    <message>
        <source>saved %1</source>
        <translation>saved %1</translation>
    </message>
    <message>
        <source>from controller id %1</source>
        <translation>from controller id %1</translation>
    </message>
    <message>
        <source>Opening a profile writes nothing. Check the rows to write, then Apply.</source>
        <translation>Opening a profile writes nothing. Check the rows to write, then Apply.</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Apply</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Controller</source>
        <translation>Controller</translation>
    </message>
    <message>
        <source>Profile</source>
        <translation>Profile</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Unit</translation>
    </message>
    <message>
        <source>Key</source>
        <translation>Key</translation>
    </message>
    <message>
        <source>Differences only</source>
        <translation>Differences only</translation>
    </message>
    <message>
        <source>Also apply the device id and baud (the connection follows)</source>
        <translation>Also apply the device id and baud (the connection follows)</translation>
    </message>
    <message>
        <source>Check differing</source>
        <translation>Check differing</translation>
    </message>
    <message>
        <source>Check none</source>
        <translation>Check none</translation>
    </message>
    <message>
        <source>Apply checked</source>
        <translation>Apply checked</translation>
    </message>
    <message>
        <source>Save to flash</source>
        <translation>Save to flash</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Close</translation>
    </message>
    <message>
        <source>Not applied:</source>
        <translation>Not applied:</translation>
    </message>
    <message>
        <source>Left out, not supported by this controller: %1.</source>
        <translation>Left out, not supported by this controller: %1.</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) the controller already held.</source>
        <translation>
            <numerusform>%n value the controller already held.</numerusform>
            <numerusform>%n values the controller already held.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>stepcom::ProfileDiff</name>
    <message>
        <source>%1: the profile holds no value</source>
        <translation>%1: the profile holds no value</translation>
    </message>
    <message>
        <source>(unknown)</source>
        <translation>(unknown)</translation>
    </message>
    <message>
        <source>(not in the profile)</source>
        <translation>(not in the profile)</translation>
    </message>
</context>
<context>
    <name>stepcom::ProfileDocument</name>
    <message>
        <source>new profile</source>
        <translation>new profile</translation>
    </message>
    <message>
        <source>a controller is connected: open the profile to compare it instead</source>
        <translation>a controller is connected: open the profile to compare it instead</translation>
    </message>
    <message>
        <source>a controller is connected: disconnect to edit a profile without it</source>
        <translation>a controller is connected: disconnect to edit a profile without it</translation>
    </message>
    <message>
        <source>Factory values</source>
        <translation>Factory values</translation>
    </message>
    <message>
        <source>no profile is being edited</source>
        <translation>no profile is being edited</translation>
    </message>
</context>
<context>
    <name>stepcom::ProfileFile</name>
    <message>
        <source>null</source>
        <translation>null</translation>
    </message>
    <message>
        <source>true/false</source>
        <translation>true/false</translation>
    </message>
    <message>
        <source>a number</source>
        <translation>a number</translation>
    </message>
    <message>
        <source>a text &quot;%1&quot;</source>
        <translation>a text &quot;%1&quot;</translation>
    </message>
    <message>
        <source>a list</source>
        <translation>a list</translation>
    </message>
    <message>
        <source>an object</source>
        <translation>an object</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>nothing</translation>
    </message>
    <message>
        <source>the key &quot;%1&quot; appears more than once</source>
        <translation>the key &quot;%1&quot; appears more than once</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: the key &quot;%2&quot; appears more than once</source>
        <translation>&quot;%1&quot;: the key &quot;%2&quot; appears more than once</translation>
    </message>
    <message>
        <source>the file is empty</source>
        <translation>the file is empty</translation>
    </message>
    <message>
        <source>the file is %1 bytes: far too large for a profile</source>
        <translation>the file is %1 bytes: far too large for a profile</translation>
    </message>
    <message>
        <source>not valid JSON at line %1, column %2: %3</source>
        <translation>not valid JSON at line %1, column %2: %3</translation>
    </message>
    <message>
        <source>the file holds a JSON list, not a profile object</source>
        <translation>the file holds a JSON list, not a profile object</translation>
    </message>
    <message>
        <source>… and %1 more problems</source>
        <translation>… and %1 more problems</translation>
    </message>
    <message>
        <source>unknown field &quot;%1&quot; (allowed: %2)</source>
        <translation>unknown field &quot;%1&quot; (allowed: %2)</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: unknown field &quot;%2&quot; (allowed: %3)</source>
        <translation>&quot;%1&quot;: unknown field &quot;%2&quot; (allowed: %3)</translation>
    </message>
    <message>
        <source>this is a register map, not a profile</source>
        <translation>this is a register map, not a profile</translation>
    </message>
    <message>
        <source>not a StepCom profile: &quot;format&quot; must be &quot;%1&quot;, found %2</source>
        <translation>not a StepCom profile: &quot;format&quot; must be &quot;%1&quot;, found %2</translation>
    </message>
    <message>
        <source>&quot;schema&quot; must be a whole number, found %1</source>
        <translation>&quot;schema&quot; must be a whole number, found %1</translation>
    </message>
    <message>
        <source>profile schema %1 is newer than this StepCom reads (%2): update StepCom</source>
        <translation>profile schema %1 is newer than this StepCom reads (%2): update StepCom</translation>
    </message>
    <message>
        <source>profile schema %1 is unknown (this StepCom reads %2)</source>
        <translation>profile schema %1 is unknown (this StepCom reads %2)</translation>
    </message>
    <message>
        <source>&quot;map&quot; must be an object {&quot;id&quot;: …, &quot;version&quot;: …}, found %1</source>
        <translation>&quot;map&quot; must be an object {&quot;id&quot;: …, &quot;version&quot;: …}, found %1</translation>
    </message>
    <message>
        <source>&quot;map&quot;: &quot;id&quot; must be a text, found %1</source>
        <translation>&quot;map&quot;: &quot;id&quot; must be a text, found %1</translation>
    </message>
    <message>
        <source>&quot;map&quot;: &quot;version&quot; must be a whole number, found %1</source>
        <translation>&quot;map&quot;: &quot;version&quot; must be a whole number, found %1</translation>
    </message>
    <message>
        <source>the profile is for register map &quot;%1&quot; version %2, but the controller&apos;s map is &quot;%3&quot; version %4</source>
        <translation>the profile is for register map &quot;%1&quot; version %2, but the controller&apos;s map is &quot;%3&quot; version %4</translation>
    </message>
    <message>
        <source>&quot;metadata&quot; must be an object, found %1</source>
        <translation>&quot;metadata&quot; must be an object, found %1</translation>
    </message>
    <message>
        <source>&quot;metadata&quot;: &quot;%1&quot; must be a text, found %2</source>
        <translation>&quot;metadata&quot;: &quot;%1&quot; must be a text, found %2</translation>
    </message>
    <message>
        <source>&quot;metadata&quot;: &quot;created&quot; is not a date and time (2024-05-31T14:02:00Z): &quot;%1&quot;</source>
        <translation>&quot;metadata&quot;: &quot;created&quot; is not a date and time (2024-05-31T14:02:00Z): &quot;%1&quot;</translation>
    </message>
    <message>
        <source>&quot;metadata&quot;: &quot;%1&quot; must be a %2, found %3</source>
        <translation>&quot;metadata&quot;: &quot;%1&quot; must be a %2, found %3</translation>
    </message>
    <message>
        <source>whole number</source>
        <translation>whole number</translation>
    </message>
    <message>
        <source>&quot;values&quot; must be an object of key: value, found %1</source>
        <translation>&quot;values&quot; must be an object of key: value, found %1</translation>
    </message>
    <message>
        <source>unknown parameter &quot;%1&quot; (not in register map &quot;%2&quot;)</source>
        <translation>unknown parameter &quot;%1&quot; (not in register map &quot;%2&quot;)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is a command, not a setting</source>
        <translation>&quot;%1&quot; is a command, not a setting</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is read-only (a status value), not a setting</source>
        <translation>&quot;%1&quot; is read-only (a status value), not a setting</translation>
    </message>
    <message>
        <source>%1: expected a number, found %2</source>
        <translation>%1: expected a number, found %2</translation>
    </message>
    <message>
        <source>missing &quot;%1&quot; (%2)</source>
        <translation>missing &quot;%1&quot; (%2)</translation>
    </message>
    <message>
        <source>no register map to check the profile against</source>
        <translation>no register map to check the profile against</translation>
    </message>
    <message>
        <source>%1: no such file</source>
        <translation>%1: no such file</translation>
    </message>
    <message>
        <source>%1: %2 bytes, far too large for a profile</source>
        <translation>%1: %2 bytes, far too large for a profile</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>cannot write %1: %2</translation>
    </message>
    <message>
        <source>not in register map &quot;%1&quot;</source>
        <translation>not in register map &quot;%1&quot;</translation>
    </message>
    <message>
        <source>a command in register map &quot;%1&quot;, not a setting</source>
        <translation>a command in register map &quot;%1&quot;, not a setting</translation>
    </message>
    <message>
        <source>a status value in register map &quot;%1&quot;, not a setting</source>
        <translation>a status value in register map &quot;%1&quot;, not a setting</translation>
    </message>
    <message>
        <source>&quot;stepcom&quot; must be an object, found %1</source>
        <translation>&quot;stepcom&quot; must be an object, found %1</translation>
    </message>
    <message>
        <source>&quot;metadata&quot;: &quot;backup&quot; must be {&quot;operation&quot;: one of %1, &quot;device&quot;: text}</source>
        <translation>&quot;metadata&quot;: &quot;backup&quot; must be {&quot;operation&quot;: one of %1, &quot;device&quot;: text}</translation>
    </message>
    <message>
        <source>&quot;metadata&quot;: &quot;backup&quot;: &quot;device&quot; must be a text of at most 200 characters</source>
        <translation>&quot;metadata&quot;: &quot;backup&quot;: &quot;device&quot; must be a text of at most 200 characters</translation>
    </message>
    <message>
        <source>&quot;metadata&quot;: &quot;unsupported&quot; must be a list of keys, found %1</source>
        <translation>&quot;metadata&quot;: &quot;unsupported&quot; must be a list of keys, found %1</translation>
    </message>
    <message>
        <source>&quot;metadata&quot;: &quot;unsupported&quot;: %1 is no parameter of the map</source>
        <translation>&quot;metadata&quot;: &quot;unsupported&quot;: %1 is no parameter of the map</translation>
    </message>
    <message>
        <source>&quot;metadata&quot;: &quot;source&quot; is &quot;simulator&quot; or absent, found &quot;%1&quot;</source>
        <translation>&quot;metadata&quot;: &quot;source&quot; is &quot;simulator&quot; or absent, found &quot;%1&quot;</translation>
    </message>
</context>
<context>
    <name>stepcom::ProfileFilesDialog</name>
    <message>
        <source>differ</source>
        <translation>differ</translation>
    </message>
    <message>
        <source>the same</source>
        <translation>the same</translation>
    </message>
    <message>
        <source>only in A</source>
        <translation>only in A</translation>
    </message>
    <message>
        <source>only in B</source>
        <translation>only in B</translation>
    </message>
    <message>
        <source>outside this map</source>
        <translation>outside this map</translation>
    </message>
    <message>
        <source>Motor %1 · %2</source>
        <translation>Motor %1 · %2</translation>
    </message>
    <message>
        <source>(not a setting of this map)</source>
        <translation>(not a setting of this map)</translation>
    </message>
    <message>
        <source>%1 differ, %2 only in A, %3 only in B, %4 outside this map (%5 of them differ).</source>
        <translation>%1 differ, %2 only in A, %3 only in B, %4 outside this map (%5 of them differ).</translation>
    </message>
    <message>
        <source>The files hold the same values.</source>
        <translation>The files hold the same values.</translation>
    </message>
    <message>
        <source>The files differ.</source>
        <translation>The files differ.</translation>
    </message>
    <message>
        <source>Compare profiles: %1 and %2</source>
        <translation>Compare profiles: %1 and %2</translation>
    </message>
    <message>
        <source>%1 = %2</source>
        <translation>%1 = %2</translation>
    </message>
    <message>
        <source>register map %1</source>
        <translation>register map %1</translation>
    </message>
    <message>
        <source>Two files compared against register map %1/%2; no controller is read or written.</source>
        <translation>Two files compared against register map %1/%2; no controller is read or written.</translation>
    </message>
    <message>
        <source>Group</source>
        <translation>Group</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>A</source>
        <translation>A</translation>
    </message>
    <message>
        <source>B</source>
        <translation>B</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Unit</translation>
    </message>
    <message>
        <source>Key</source>
        <translation>Key</translation>
    </message>
    <message>
        <source>Differences only</source>
        <translation>Differences only</translation>
    </message>
</context>
<context>
    <name>stepcom::ProfileRollout</name>
    <message>
        <source>could not be read: %1</source>
        <translation>could not be read: %1</translation>
    </message>
    <message>
        <source>it already holds the profile&apos;s values</source>
        <translation>it already holds the profile&apos;s values</translation>
    </message>
    <message>
        <source>no value was chosen for it</source>
        <translation>no value was chosen for it</translation>
    </message>
    <message>
        <source>not every value could be verified</source>
        <translation>not every value could be verified</translation>
    </message>
    <message>
        <source>not done: E-STOP</source>
        <translation>not done: E-STOP</translation>
    </message>
    <message>
        <source>id %1</source>
        <translation>id %1</translation>
    </message>
    <message>
        <source>id %1 (%2)</source>
        <translation>id %1 (%2)</translation>
    </message>
    <message>
        <source>%1: waiting</source>
        <translation>%1: waiting</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n value(s) differ</source>
        <translation>
            <numerusform>%1: %n value differ</numerusform>
            <numerusform>%1: %n values differ</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1: written and verified, %n value(s)</source>
        <translation>
            <numerusform>%1: written and verified, %n value</numerusform>
            <numerusform>%1: written and verified, %n values</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: skipped, %2</source>
        <translation>%1: skipped, %2</translation>
    </message>
    <message>
        <source>%1: FAILED, %2</source>
        <translation>%1: FAILED, %2</translation>
    </message>
    <message numerus="yes">
        <source>%1: FAILED, %2 (%n value(s) verified)</source>
        <translation>
            <numerusform>%1: FAILED, %2 (%n value verified)</numerusform>
            <numerusform>%1: FAILED, %2 (%n values verified)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>stepcom::ProfileSaveDialog</name>
    <message>
        <source>Controller id %1</source>
        <translation>Controller id %1</translation>
    </message>
    <message>
        <source>Profile</source>
        <translation>Profile</translation>
    </message>
    <message>
        <source>Save profile</source>
        <translation>Save profile</translation>
    </message>
    <message>
        <source>Every parameter is read from the controller, then saved with this name and notes.</source>
        <translation>Every parameter is read from the controller, then saved with this name and notes.</translation>
    </message>
    <message>
        <source>The values the pages show (edits included) are saved with this name and notes.</source>
        <translation>The values the pages show (edits included) are saved with this name and notes.</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Name:</translation>
    </message>
    <message>
        <source>N&amp;otes:</source>
        <translation>N&amp;otes:</translation>
    </message>
    <message>
        <source>Machine, place, who set it up, what was changed</source>
        <translation>Machine, place, who set it up, what was changed</translation>
    </message>
</context>
<context>
    <name>stepcom::ProfileVariance</name>
    <message>
        <source>the profile was made with register map &quot;%1&quot;; this map is &quot;%2&quot;: only the settings both have can be applied</source>
        <translation>the profile was made with register map &quot;%1&quot;; this map is &quot;%2&quot;: only the settings both have can be applied</translation>
    </message>
    <message>
        <source>unknown to this map: %1 = %2 (%3)</source>
        <translation>unknown to this map: %1 = %2 (%3)</translation>
    </message>
    <message>
        <source>cannot be applied: %1</source>
        <translation>cannot be applied: %1</translation>
    </message>
    <message>
        <source>not in the profile: %1 (%2)</source>
        <translation>not in the profile: %1 (%2)</translation>
    </message>
</context>
<context>
    <name>stepcom::ProofDrive</name>
    <message>
        <source>There is no motor %1 (this controller has %2)</source>
        <translation>There is no motor %1 (this controller has %2)</translation>
    </message>
    <message>
        <source>This register map has no %1 for motor %2: the axis cannot be proven</source>
        <translation>This register map has no %1 for motor %2: the axis cannot be proven</translation>
    </message>
    <message>
        <source>Not connected: nothing was sent</source>
        <translation>Not connected: nothing was sent</translation>
    </message>
    <message>
        <source>Motor %1: its values could not be read (%2): nothing was moved</source>
        <translation>Motor %1: its values could not be read (%2): nothing was moved</translation>
    </message>
    <message>
        <source>Motor %1: its step angle, microsteps or pitch is 0: the axis cannot be proven</source>
        <translation>Motor %1: its step angle, microsteps or pitch is 0: the axis cannot be proven</translation>
    </message>
    <message>
        <source>Motor %1: the test speed could not be written (%2)</source>
        <translation>Motor %1: the test speed could not be written (%2)</translation>
    </message>
    <message>
        <source>This register map has no input %1</source>
        <translation>This register map has no input %1</translation>
    </message>
    <message>
        <source>the home input could not be read (%1)</source>
        <translation>the home input could not be read (%1)</translation>
    </message>
    <message>
        <source>speed %1 %2, acceleration %3 %4</source>
        <translation>speed %1 %2, acceleration %3 %4</translation>
    </message>
    <message>
        <source>Motor %1&apos;s own %2 are as they were.</source>
        <translation>Motor %1&apos;s own %2 are as they were.</translation>
    </message>
    <message>
        <source>Motor %1&apos;s own %2 could not be put back: not connected. Write them again once the controller answers.</source>
        <translation>Motor %1&apos;s own %2 could not be put back: not connected. Write them again once the controller answers.</translation>
    </message>
    <message>
        <source>Motor %1&apos;s own %2 could not be put back: %3</source>
        <translation>Motor %1&apos;s own %2 could not be put back: %3</translation>
    </message>
    <message>
        <source>Motor %1&apos;s own %2 are back (verified).</source>
        <translation>Motor %1&apos;s own %2 are back (verified).</translation>
    </message>
    <message>
        <source>Stopped: the motor was stopped</source>
        <translation>Stopped: the motor was stopped</translation>
    </message>
    <message>
        <source>E-STOP: the test ended at once</source>
        <translation>E-STOP: the test ended at once</translation>
    </message>
    <message>
        <source>The link was lost: the test ended</source>
        <translation>The link was lost: the test ended</translation>
    </message>
    <message>
        <source>The controller restarted: the test ended</source>
        <translation>The controller restarted: the test ended</translation>
    </message>
    <message>
        <source>Motor %1 has no home input set (%2 is 0): the test references on the home switch, so nothing was moved</source>
        <translation>Motor %1 has no home input set (%2 is 0): the test references on the home switch, so nothing was moved</translation>
    </message>
</context>
<context>
    <name>stepcom::ProofResult</name>
    <message>
        <source>%1. %2</source>
        <translation>%1. %2</translation>
    </message>
</context>
<context>
    <name>stepcom::Reader</name>
    <message>
        <source>unknown key</source>
        <translation>unknown key</translation>
    </message>
    <message>
        <source>must be a number</source>
        <translation>must be a number</translation>
    </message>
    <message>
        <source>%1 is out of range (%2 to %3)</source>
        <translation>%1 is out of range (%2 to %3)</translation>
    </message>
    <message>
        <source>must be a whole number</source>
        <translation>must be a whole number</translation>
    </message>
    <message>
        <source>must be true or false</source>
        <translation>must be true or false</translation>
    </message>
    <message>
        <source>must be an object</source>
        <translation>must be an object</translation>
    </message>
</context>
<context>
    <name>stepcom::ReferenceTracker</name>
    <message>
        <source>referenced</source>
        <translation>referenced</translation>
    </message>
    <message>
        <source>not referenced (not homed yet)</source>
        <translation>not referenced (not homed yet)</translation>
    </message>
    <message>
        <source>not referenced (homing ended without the home input)</source>
        <translation>not referenced (homing ended without the home input)</translation>
    </message>
    <message>
        <source>not referenced (homing was interrupted)</source>
        <translation>not referenced (homing was interrupted)</translation>
    </message>
    <message>
        <source>not referenced (E-STOP)</source>
        <translation>not referenced (E-STOP)</translation>
    </message>
    <message>
        <source>not referenced (coordinates zeroed)</source>
        <translation>not referenced (coordinates zeroed)</translation>
    </message>
    <message>
        <source>not referenced (link lost)</source>
        <translation>not referenced (link lost)</translation>
    </message>
    <message>
        <source>not referenced (the controller restarted)</source>
        <translation>not referenced (the controller restarted)</translation>
    </message>
    <message>
        <source>reference not known (no answer while it moved: the controller may have restarted)</source>
        <translation>reference not known (no answer while it moved: the controller may have restarted)</translation>
    </message>
</context>
<context>
    <name>stepcom::RegisterMap</name>
    <message>
        <source>%1: not a register map file (not a regular file)</source>
        <translation>%1: not a register map file (not a regular file)</translation>
    </message>
    <message>
        <source>%1: %2 bytes is too large for a register map (at most %3 MiB)</source>
        <translation>%1: %2 bytes is too large for a register map (at most %3 MiB)</translation>
    </message>
</context>
<context>
    <name>stepcom::ReplayBar</name>
    <message>
        <source>id %1</source>
        <translation>id %1</translation>
    </message>
    <message>
        <source>line</source>
        <translation>line</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Play</translation>
    </message>
    <message>
        <source>Play the log at the chosen speed, or hold it at this moment</source>
        <translation>Play the log at the chosen speed, or hold it at this moment</translation>
    </message>
    <message>
        <source>Replay speed</source>
        <translation>Replay speed</translation>
    </message>
    <message>
        <source>◀ Frame</source>
        <translation>◀ Frame</translation>
    </message>
    <message>
        <source>The frame before this moment</source>
        <translation>The frame before this moment</translation>
    </message>
    <message>
        <source>Frame ▶</source>
        <translation>Frame ▶</translation>
    </message>
    <message>
        <source>The next frame after this moment</source>
        <translation>The next frame after this moment</translation>
    </message>
    <message>
        <source>Moment of the log</source>
        <translation>Moment of the log</translation>
    </message>
    <message>
        <source>Time from the start of the log (clock time)</source>
        <translation>Time from the start of the log (clock time)</translation>
    </message>
    <message>
        <source>◀ Event</source>
        <translation>◀ Event</translation>
    </message>
    <message>
        <source>The event before this moment</source>
        <translation>The event before this moment</translation>
    </message>
    <message>
        <source>Event ▶</source>
        <translation>Event ▶</translation>
    </message>
    <message>
        <source>The next event after this moment</source>
        <translation>The next event after this moment</translation>
    </message>
    <message>
        <source>Events of the log</source>
        <translation>Events of the log</translation>
    </message>
    <message>
        <source>Writes, commands, E-STOPs, errors, the link and restarts; choose one to see that moment</source>
        <translation>Writes, commands, E-STOPs, errors, the link and restarts; choose one to see that moment</translation>
    </message>
    <message>
        <source>&amp;Device:</source>
        <translation>&amp;Device:</translation>
    </message>
    <message>
        <source>The controller of the line shown on the pages</source>
        <translation>The controller of the line shown on the pages</translation>
    </message>
    <message>
        <source>Close replay</source>
        <translation>Close replay</translation>
    </message>
    <message>
        <source>Leave the replay; the window is empty again, ready to connect</source>
        <translation>Leave the replay; the window is empty again, ready to connect</translation>
    </message>
    <message numerus="yes">
        <source>… %n more event(s): Event ▶ reaches them</source>
        <translation>
            <numerusform>… %n more event: Event ▶ reaches them</numerusform>
            <numerusform>… %n more events: Event ▶ reaches them</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>stepcom::ReplayDecoder</name>
    <message>
        <source>late answer (discarded): %1</source>
        <translation>late answer (discarded): %1</translation>
    </message>
    <message>
        <source>no answer: %1</source>
        <translation>no answer: %1</translation>
    </message>
    <message>
        <source>E-STOP sent, not acknowledged</source>
        <translation>E-STOP sent, not acknowledged</translation>
    </message>
    <message>
        <source>refused (%1): %2</source>
        <translation>refused (%1): %2</translation>
    </message>
    <message>
        <source>E-STOP acknowledged</source>
        <translation>E-STOP acknowledged</translation>
    </message>
</context>
<context>
    <name>stepcom::ReplayLog</name>
    <message>
        <source>lines not of a session log, skipped: %1 (line %2)</source>
        <translation>lines not of a session log, skipped: %1 (line %2)</translation>
    </message>
    <message>
        <source>the log ends in the middle of line %1 (cut short?): that line is left out</source>
        <translation>the log ends in the middle of line %1 (cut short?): that line is left out</translation>
    </message>
    <message>
        <source>events not listed (too many): %1</source>
        <translation>events not listed (too many): %1</translation>
    </message>
    <message>
        <source>line %1: the log was recorded with the register map %2, not with %3 (open it with that map)</source>
        <translation>line %1: the log was recorded with the register map %2, not with %3 (open it with that map)</translation>
    </message>
    <message>
        <source>%1: no such file</source>
        <translation>%1: no such file</translation>
    </message>
    <message>
        <source>%1 is empty</source>
        <translation>%1 is empty</translation>
    </message>
    <message>
        <source>%1 is a zip file, not a session log (a support bundle? open it as one)</source>
        <translation>%1 is a zip file, not a session log (a support bundle? open it as one)</translation>
    </message>
    <message>
        <source>%1 holds no frames, only its header</source>
        <translation>%1 holds no frames, only its header</translation>
    </message>
    <message>
        <source>%1 is not a StepCom session log: not one of its lines is one (%2 lines)</source>
        <translation>%1 is not a StepCom session log: not one of its lines is one (%2 lines)</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>cannot read %1: %2</translation>
    </message>
    <message>
        <source>opening %1 was cancelled</source>
        <translation>opening %1 was cancelled</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a time: give seconds from the start (12.5) or a clock time hh:mm:ss[.mmm]</source>
        <translation>&apos;%1&apos; is not a time: give seconds from the start (12.5) or a clock time hh:mm:ss[.mmm]</translation>
    </message>
    <message>
        <source>%1 is before the log&apos;s start (%2)</source>
        <translation>%1 is before the log&apos;s start (%2)</translation>
    </message>
</context>
<context>
    <name>stepcom::ReplayMode</name>
    <message>
        <source>Replay of %1 — nothing is written or moved. The pages show what the log says the controller held at the moment chosen below; connect or close the replay to work with a controller.</source>
        <translation>Replay of %1 — nothing is written or moved. The pages show what the log says the controller held at the moment chosen below; connect or close the replay to work with a controller.</translation>
    </message>
    <message>
        <source>Open session &amp;log…</source>
        <translation>Open session &amp;log…</translation>
    </message>
    <message>
        <source>Replay a session log or a support bundle: see what the window showed then, without a controller (%1)</source>
        <translation>Replay a session log or a support bundle: see what the window showed then, without a controller (%1)</translation>
    </message>
    <message>
        <source>Close re&amp;play</source>
        <translation>Close re&amp;play</translation>
    </message>
    <message>
        <source>A session log is being opened already.</source>
        <translation>A session log is being opened already.</translation>
    </message>
    <message>
        <source>Disconnect from the controller before replaying a log: a replay shows the log&apos;s values where the controller&apos;s are.</source>
        <translation>Disconnect from the controller before replaying a log: a replay shows the log&apos;s values where the controller&apos;s are.</translation>
    </message>
    <message>
        <source>Close the profile file before replaying a log.</source>
        <translation>Close the profile file before replaying a log.</translation>
    </message>
    <message>
        <source>Open session log</source>
        <translation>Open session log</translation>
    </message>
    <message>
        <source>Session logs and support bundles (*.log *.txt *.zip);;All files (*)</source>
        <translation>Session logs and support bundles (*.log *.txt *.zip);;All files (*)</translation>
    </message>
    <message>
        <source>%1 cannot be replayed: %2</source>
        <translation>%1 cannot be replayed: %2</translation>
    </message>
    <message numerus="yes">
        <source>%1 holds %n session log(s). Which one to replay?</source>
        <translation>
            <numerusform>%1 holds %n session log. Which one to replay?</numerusform>
            <numerusform>%1 holds %n session logs. Which one to replay?</numerusform>
        </translation>
    </message>
    <message>
        <source>Reading %1…</source>
        <translation>Reading %1…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <source>Opening %1 was cancelled.</source>
        <translation>Opening %1 was cancelled.</translation>
    </message>
    <message numerus="yes">
        <source>Replaying %1: %2 s, %n event(s).</source>
        <translation>
            <numerusform>Replaying %1: %2 s, %n event.</numerusform>
            <numerusform>Replaying %1: %2 s, %n events.</numerusform>
        </translation>
    </message>
    <message>
        <source>Warning: %1.</source>
        <translation>Warning: %1.</translation>
    </message>
    <message>
        <source>Replay of %1 closed.</source>
        <translation>Replay of %1 closed.</translation>
    </message>
    <message>
        <source>Its last error, at %1: %2.</source>
        <translation>Its last error, at %1: %2.</translation>
    </message>
    <message>
        <source>At this moment the link is up.</source>
        <translation>At this moment the link is up.</translation>
    </message>
    <message>
        <source>At this moment the link is down.</source>
        <translation>At this moment the link is down.</translation>
    </message>
    <message>
        <source>Id %1 answers.</source>
        <translation>Id %1 answers.</translation>
    </message>
    <message>
        <source>Id %1 does not answer.</source>
        <translation>Id %1 does not answer.</translation>
    </message>
    <message>
        <source>StepCom is trying to reconnect to the controller: cancel that before replaying a log.</source>
        <translation>StepCom is trying to reconnect to the controller: cancel that before replaying a log.</translation>
    </message>
    <message>
        <source>replay: %1</source>
        <translation>replay: %1</translation>
    </message>
</context>
<context>
    <name>stepcom::ReplayState</name>
    <message>
        <source>(unknown)</source>
        <translation>(unknown)</translation>
    </message>
</context>
<context>
    <name>stepcom::ReportFile</name>
    <message>
        <source>cannot write %1: %2</source>
        <translation>cannot write %1: %2</translation>
    </message>
    <message>
        <source>%1: the report is written as .pdf or .html, not .%2</source>
        <translation>%1: the report is written as .pdf or .html, not .%2</translation>
    </message>
</context>
<context>
    <name>stepcom::RestartWatch</name>
    <message>
        <source>it answers again after %1 s without an answer</source>
        <translation>it answers again after %1 s without an answer</translation>
    </message>
    <message>
        <source>its positions went back to 0 where an axis stood still, with no command</source>
        <translation>its positions went back to 0 where an axis stood still, with no command</translation>
    </message>
    <message>
        <source>motor %1 stood still at %2 and reads %3</source>
        <translation>motor %1 stood still at %2 and reads %3</translation>
    </message>
    <message>
        <source>motor %1 stood still at %2</source>
        <translation>motor %1 stood still at %2</translation>
    </message>
    <message>
        <source>motor %1 was moving and reads %2</source>
        <translation>motor %1 was moving and reads %2</translation>
    </message>
    <message>
        <source>; </source>
        <comment>between what was seen</comment>
        <translation>; </translation>
    </message>
</context>
<context>
    <name>stepcom::RoundTrips</name>
    <message>
        <source>%1-%2 ms (median %3 ms)</source>
        <translation>%1-%2 ms (median %3 ms)</translation>
    </message>
</context>
<context>
    <name>stepcom::RtuTransport</name>
    <message>
        <source>%1 is not a serial port (give the adapter&apos;s device, e.g. /dev/ttyUSB0 or a /dev/serial/by-id/ link)</source>
        <translation>%1 is not a serial port (give the adapter&apos;s device, e.g. /dev/ttyUSB0 or a /dev/serial/by-id/ link)</translation>
    </message>
    <message>
        <source>the converter closed the connection</source>
        <translation>the converter closed the connection</translation>
    </message>
    <message>
        <source>cannot open %1: %2</source>
        <translation>cannot open %1: %2</translation>
    </message>
    <message>
        <source>bytes that arrived between two requests</source>
        <translation>bytes that arrived between two requests</translation>
    </message>
    <message>
        <source>bytes that are no answer frame</source>
        <translation>bytes that are no answer frame</translation>
    </message>
    <message>
        <source>an answer with a bad checksum (CRC)</source>
        <translation>an answer with a bad checksum (CRC)</translation>
    </message>
    <message>
        <source>an answer from device %1, not %2</source>
        <translation>an answer from device %1, not %2</translation>
    </message>
    <message>
        <source>a late answer to an earlier request</source>
        <translation>a late answer to an earlier request</translation>
    </message>
    <message>
        <source>an incomplete answer</source>
        <translation>an incomplete answer</translation>
    </message>
</context>
<context>
    <name>stepcom::SequenceCheck</name>
    <message>
        <source>%1: the run has too many steps to check its positions (more than %2): make it shorter or use fewer cycles</source>
        <translation>%1: the run has too many steps to check its positions (more than %2): make it shorter or use fewer cycles</translation>
    </message>
    <message>
        <source>motor %1 would go to %2 %3, outside the file&apos;s limits (%4 .. %5 %3)</source>
        <translation>motor %1 would go to %2 %3, outside the file&apos;s limits (%4 .. %5 %3)</translation>
    </message>
    <message>
        <source>the controller&apos;s homing order (40177, 40178) names no motor: &quot;home&quot;: &quot;order&quot; homes nothing</source>
        <translation>the controller&apos;s homing order (40177, 40178) names no motor: &quot;home&quot;: &quot;order&quot; homes nothing</translation>
    </message>
    <message>
        <source>motor %1 is not referenced: a move_to needs a home step before it (or the axis referenced already)</source>
        <translation>motor %1 is not referenced: a move_to needs a home step before it (or the axis referenced already)</translation>
    </message>
</context>
<context>
    <name>stepcom::SequenceEditor</name>
    <message>
        <source>&amp;Add step</source>
        <translation>&amp;Add step</translation>
    </message>
    <message>
        <source>&amp;Remove</source>
        <translation>&amp;Remove</translation>
    </message>
    <message>
        <source>Up</source>
        <translation>Up</translation>
    </message>
    <message>
        <source>Down</source>
        <translation>Down</translation>
    </message>
    <message>
        <source>Into the loop above</source>
        <translation>Into the loop above</translation>
    </message>
    <message>
        <source>Out of the loop</source>
        <translation>Out of the loop</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>Steps</translation>
    </message>
</context>
<context>
    <name>stepcom::SequenceMove</name>
    <message>
        <source>A move is still running: wait for it to end</source>
        <translation>A move is still running: wait for it to end</translation>
    </message>
</context>
<context>
    <name>stepcom::SequencePage</name>
    <message>
        <source>Sequence</source>
        <translation>Sequence</translation>
    </message>
    <message>
        <source>(new sequence)</source>
        <translation>(new sequence)</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>Points</translation>
    </message>
    <message>
        <source>Path</source>
        <translation>Path</translation>
    </message>
    <message>
        <source>The sequence has changes that are not saved. Discard them?</source>
        <translation>The sequence has changes that are not saved. Discard them?</translation>
    </message>
    <message>
        <source>Open a sequence</source>
        <translation>Open a sequence</translation>
    </message>
    <message>
        <source>%1 was not opened: the sequence is as it was.</source>
        <translation>%1 was not opened: the sequence is as it was.</translation>
    </message>
    <message>
        <source>Save the sequence</source>
        <translation>Save the sequence</translation>
    </message>
    <message>
        <source>Not saved: the sequence could not be read back as a file.</source>
        <translation>Not saved: the sequence could not be read back as a file.</translation>
    </message>
    <message>
        <source>%1 was not saved: %2</source>
        <translation>%1 was not saved: %2</translation>
    </message>
    <message>
        <source>Any earlier file there is as it was.</source>
        <translation>Any earlier file there is as it was.</translation>
    </message>
    <message>
        <source>StepCom sequences (*.stepseq);;All files (*)</source>
        <translation>StepCom sequences (*.stepseq);;All files (*)</translation>
    </message>
    <message>
        <source>StepCom sequences (*.stepseq)</source>
        <translation>StepCom sequences (*.stepseq)</translation>
    </message>
    <message>
        <source>a new sequence, not saved</source>
        <translation>a new sequence, not saved</translation>
    </message>
    <message>
        <source>Sequence: %1%2</source>
        <translation>Sequence: %1%2</translation>
    </message>
    <message>
        <source> (changed)</source>
        <translation> (changed)</translation>
    </message>
    <message>
        <source>motor %1 %2 .. %3 %4</source>
        <translation>motor %1 %2 .. %3 %4</translation>
    </message>
    <message>
        <source>The file sets no limits of its own; StepCom&apos;s travel limits (Jog page) apply.</source>
        <translation>The file sets no limits of its own; StepCom&apos;s travel limits (Jog page) apply.</translation>
    </message>
    <message>
        <source>The file&apos;s limits: %1; StepCom&apos;s travel limits apply too.</source>
        <translation>The file&apos;s limits: %1; StepCom&apos;s travel limits apply too.</translation>
    </message>
    <message>
        <source>Path (motor 1 across, motor 2 up)</source>
        <translation>Path (motor 1 across, motor 2 up)</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>Steps</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Run</translation>
    </message>
    <message>
        <source>All outputs &amp;off when the run stops</source>
        <translation>All outputs &amp;off when the run stops</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;New</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Open…</translation>
    </message>
    <message>
        <source>Sa&amp;ve</source>
        <translation>Sa&amp;ve</translation>
    </message>
    <message>
        <source>Save &amp;as…</source>
        <translation>Save &amp;as…</translation>
    </message>
    <message>
        <source>motor 1</source>
        <translation>motor 1</translation>
    </message>
    <message>
        <source>motor 2</source>
        <translation>motor 2</translation>
    </message>
    <message>
        <source>No steps yet: jog to each point and teach it, then Add step (or open a .stepseq file).</source>
        <translation>No steps yet: jog to each point and teach it, then Add step (or open a .stepseq file).</translation>
    </message>
    <message>
        <source>Teach this point (%1, %2)</source>
        <translation>Teach this point (%1, %2)</translation>
    </message>
    <message>
        <source>Point %1 taught at the place clicked.</source>
        <translation>Point %1 taught at the place clicked.</translation>
    </message>
</context>
<context>
    <name>stepcom::SequenceParser</name>
    <message>
        <source>a true/false</source>
        <translation>a true/false</translation>
    </message>
    <message>
        <source>a number</source>
        <translation>a number</translation>
    </message>
    <message>
        <source>a text</source>
        <translation>a text</translation>
    </message>
    <message>
        <source>a list</source>
        <translation>a list</translation>
    </message>
    <message>
        <source>an object</source>
        <translation>an object</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>nothing</translation>
    </message>
    <message>
        <source>unknown key &quot;%1&quot; (allowed here: %2)</source>
        <translation>unknown key &quot;%1&quot; (allowed here: %2)</translation>
    </message>
    <message>
        <source>must be %1, not %2</source>
        <translation>must be %1, not %2</translation>
    </message>
    <message>
        <source>a whole number</source>
        <translation>a whole number</translation>
    </message>
    <message>
        <source>must be a whole number from %1 to %2, not %3</source>
        <translation>must be a whole number from %1 to %2, not %3</translation>
    </message>
    <message>
        <source>unknown axis &quot;%1&quot; (this controller has motor1 .. motor%2)</source>
        <translation>unknown axis &quot;%1&quot; (this controller has motor1 .. motor%2)</translation>
    </message>
    <message>
        <source>an object {&quot;motor1&quot;: …}</source>
        <translation>an object {&quot;motor1&quot;: …}</translation>
    </message>
    <message>
        <source>names no axis</source>
        <translation>names no axis</translation>
    </message>
    <message>
        <source>an object of named points</source>
        <translation>an object of named points</translation>
    </message>
    <message>
        <source>an object {&quot;motor1&quot;: {&quot;min&quot;: …, &quot;max&quot;: …}}</source>
        <translation>an object {&quot;motor1&quot;: {&quot;min&quot;: …, &quot;max&quot;: …}}</translation>
    </message>
    <message>
        <source>an object {&quot;min&quot;: …, &quot;max&quot;: …}</source>
        <translation>an object {&quot;min&quot;: …, &quot;max&quot;: …}</translation>
    </message>
    <message>
        <source>sets neither min nor max</source>
        <translation>sets neither min nor max</translation>
    </message>
    <message>
        <source>must be &quot;leave&quot; or &quot;all_off&quot;</source>
        <translation>must be &quot;leave&quot; or &quot;all_off&quot;</translation>
    </message>
    <message>
        <source>a list of steps</source>
        <translation>a list of steps</translation>
    </message>
    <message>
        <source>holds no step</source>
        <translation>holds no step</translation>
    </message>
    <message>
        <source>a step (an object)</source>
        <translation>a step (an object)</translation>
    </message>
    <message>
        <source>unknown key &quot;%1&quot;: a step needs one of %2</source>
        <translation>unknown key &quot;%1&quot;: a step needs one of %2</translation>
    </message>
    <message>
        <source>not a step: it needs one of %1</source>
        <translation>not a step: it needs one of %1</translation>
    </message>
    <message>
        <source>one step does one thing, not %1</source>
        <translation>one step does one thing, not %1</translation>
    </message>
    <message>
        <source>&quot;order&quot; or a motor (&quot;motor1&quot;)</source>
        <translation>&quot;order&quot; or a motor (&quot;motor1&quot;)</translation>
    </message>
    <message>
        <source>unknown point &quot;%1&quot; (the file&apos;s points: %2)</source>
        <translation>unknown point &quot;%1&quot; (the file&apos;s points: %2)</translation>
    </message>
    <message>
        <source>none</source>
        <translation>none</translation>
    </message>
    <message>
        <source>the controller has no input %1 (it has IN1 .. IN%2)</source>
        <translation>the controller has no input %1 (it has IN1 .. IN%2)</translation>
    </message>
    <message>
        <source>the controller has no output %1 (it has outputs 1 .. %2)</source>
        <translation>the controller has no output %1 (it has outputs 1 .. %2)</translation>
    </message>
    <message>
        <source>the controller cannot switch output %1 alone (only outputs with their own on/off command: output 1); use &quot;outputs&quot;: &quot;all_on&quot; or &quot;all_off&quot;</source>
        <translation>the controller cannot switch output %1 alone (only outputs with their own on/off command: output 1); use &quot;outputs&quot;: &quot;all_on&quot; or &quot;all_off&quot;</translation>
    </message>
    <message>
        <source>needs &quot;on&quot;: true or false</source>
        <translation>needs &quot;on&quot;: true or false</translation>
    </message>
    <message>
        <source>true or false</source>
        <translation>true or false</translation>
    </message>
    <message>
        <source>a number of seconds</source>
        <translation>a number of seconds</translation>
    </message>
    <message>
        <source>must be more than 0 and at most 86400 s</source>
        <translation>must be more than 0 and at most 86400 s</translation>
    </message>
    <message>
        <source>must be &quot;all_on&quot; or &quot;all_off&quot;</source>
        <translation>must be &quot;all_on&quot; or &quot;all_off&quot;</translation>
    </message>
    <message>
        <source>a repeat needs &quot;steps&quot;</source>
        <translation>a repeat needs &quot;steps&quot;</translation>
    </message>
    <message>
        <source>line %1, column %2</source>
        <translation>line %1, column %2</translation>
    </message>
    <message>
        <source>%1: not valid JSON at %2: %3</source>
        <translation>%1: not valid JSON at %2: %3</translation>
    </message>
    <message>
        <source>%1: a sequence file is one JSON object</source>
        <translation>%1: a sequence file is one JSON object</translation>
    </message>
    <message>
        <source>not a sequence file (&quot;format&quot; must be &quot;%1&quot;)</source>
        <translation>not a sequence file (&quot;format&quot; must be &quot;%1&quot;)</translation>
    </message>
    <message>
        <source>version %1 is not known (this StepCom reads version %2)</source>
        <translation>version %1 is not known (this StepCom reads version %2)</translation>
    </message>
    <message>
        <source>the file has no &quot;steps&quot;</source>
        <translation>the file has no &quot;steps&quot;</translation>
    </message>
    <message>
        <source>%1: cannot be read: %2</source>
        <translation>%1: cannot be read: %2</translation>
    </message>
</context>
<context>
    <name>stepcom::SequencePlan</name>
    <message numerus="yes">
        <source>Sequence %1: %n step(s) in the file</source>
        <translation>
            <numerusform>Sequence %1: %n step in the file</numerusform>
            <numerusform>Sequence %1: %n steps in the file</numerusform>
        </translation>
    </message>
    <message>
        <source>  point %1: %2</source>
        <translation>  point %1: %2</translation>
    </message>
    <message>
        <source>  limits motor%1: %2 .. %3 %4</source>
        <translation>  limits motor%1: %2 .. %3 %4</translation>
    </message>
    <message>
        <source>  on a stop: all outputs off</source>
        <translation>  on a stop: all outputs off</translation>
    </message>
    <message>
        <source>  on a stop: the outputs are left as they are</source>
        <translation>  on a stop: the outputs are left as they are</translation>
    </message>
    <message>
        <source>  cycles: %1 (the whole step list each time)</source>
        <translation>  cycles: %1 (the whole step list each time)</translation>
    </message>
    <message>
        <source>  then the lost-step test (lost-steps) on %1, each referenced on its home switch</source>
        <translation>  then the lost-step test (lost-steps) on %1, each referenced on its home switch</translation>
    </message>
</context>
<context>
    <name>stepcom::SequencePoints</name>
    <message>
        <source>motor %1</source>
        <translation>motor %1</translation>
    </message>
    <message>
        <source>Not taught: the position of %1 is not known (connect, and let the status poll read it).</source>
        <translation>Not taught: the position of %1 is not known (connect, and let the status poll read it).</translation>
    </message>
    <message>
        <source>Point %1 taught again at the live position.</source>
        <translation>Point %1 taught again at the live position.</translation>
    </message>
    <message>
        <source>Point %1 taught at the live position; double-click its name to rename it.</source>
        <translation>Point %1 taught at the live position; double-click its name to rename it.</translation>
    </message>
    <message>
        <source>There is a point %1 already: the name stays %2.</source>
        <translation>There is a point %1 already: the name stays %2.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; cannot name a point: use 1-40 letters, digits, _ or -.</source>
        <translation>&quot;%1&quot; cannot name a point: use 1-40 letters, digits, _ or -.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is no position: point %2 keeps motor %3 as it was.</source>
        <translation>&quot;%1&quot; is no position: point %2 keeps motor %3 as it was.</translation>
    </message>
    <message>
        <source>Point</source>
        <translation>Point</translation>
    </message>
    <message>
        <source>Motor %1 (%2)</source>
        <translation>Motor %1 (%2)</translation>
    </message>
    <message>
        <source>Motor %1</source>
        <translation>Motor %1</translation>
    </message>
    <message>
        <source>Jog motor %1:</source>
        <translation>Jog motor %1:</translation>
    </message>
    <message>
        <source>◀ Hold</source>
        <translation>◀ Hold</translation>
    </message>
    <message>
        <source>Hold ▶</source>
        <translation>Hold ▶</translation>
    </message>
    <message>
        <source>Jog motor %1 reverse (hold)</source>
        <translation>Jog motor %1 reverse (hold)</translation>
    </message>
    <message>
        <source>Jog motor %1 forward (hold)</source>
        <translation>Jog motor %1 forward (hold)</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>Points</translation>
    </message>
    <message>
        <source>&amp;Teach here</source>
        <translation>&amp;Teach here</translation>
    </message>
    <message>
        <source>A new point at the live position of every motor</source>
        <translation>A new point at the live position of every motor</translation>
    </message>
    <message>
        <source>Teach &amp;selected again</source>
        <translation>Teach &amp;selected again</translation>
    </message>
    <message>
        <source>Remove point</source>
        <translation>Remove point</translation>
    </message>
</context>
<context>
    <name>stepcom::SequenceRunPanel</name>
    <message>
        <source>Pausing after the current step…</source>
        <translation>Pausing after the current step…</translation>
    </message>
    <message>
        <source>Step %1: %2</source>
        <translation>Step %1: %2</translation>
    </message>
    <message>
        <source>Cycle %1 done in %2 s.</source>
        <translation>Cycle %1 done in %2 s.</translation>
    </message>
    <message>
        <source>Paused before %1: Step runs it, Resume goes on.</source>
        <translation>Paused before %1: Step runs it, Resume goes on.</translation>
    </message>
    <message>
        <source>The sequence has problems (listed above): nothing was sent.</source>
        <translation>The sequence has problems (listed above): nothing was sent.</translation>
    </message>
    <message>
        <source>Not connected: nothing was sent.</source>
        <translation>Not connected: nothing was sent.</translation>
    </message>
    <message>
        <source>Run the sequence</source>
        <translation>Run the sequence</translation>
    </message>
    <message>
        <source>Run it? The machine will move.</source>
        <translation>Run it? The machine will move.</translation>
    </message>
    <message>
        <source>Not started: nothing was sent.</source>
        <translation>Not started: nothing was sent.</translation>
    </message>
    <message>
        <source>The run could not start: not connected, or one is running.</source>
        <translation>The run could not start: not connected, or one is running.</translation>
    </message>
    <message>
        <source>Reading the positions and checking the run…</source>
        <translation>Reading the positions and checking the run…</translation>
    </message>
    <message>
        <source>Cycle — of %1</source>
        <translation>Cycle — of %1</translation>
    </message>
    <message>
        <source>Running sequence: cycle %1 of %2</source>
        <translation>Running sequence: cycle %1 of %2</translation>
    </message>
    <message>
        <source>Running sequence: cycle %1 of %2, step %3</source>
        <translation>Running sequence: cycle %1 of %2, step %3</translation>
    </message>
    <message>
        <source>%1 (at %2)</source>
        <translation>%1 (at %2)</translation>
    </message>
    <message>
        <source>Cycles done: %1 of %2; cycle time min %3 s, median %4 s, max %5 s</source>
        <translation>Cycles done: %1 of %2; cycle time min %3 s, median %4 s, max %5 s</translation>
    </message>
    <message>
        <source>Cycles done: %1 of %2</source>
        <translation>Cycles done: %1 of %2</translation>
    </message>
    <message>
        <source>Running sequence: the lost-step check</source>
        <translation>Running sequence: the lost-step check</translation>
    </message>
    <message>
        <source>Lost-step check: %1</source>
        <translation>Lost-step check: %1</translation>
    </message>
    <message>
        <source>C&amp;ycles:</source>
        <translation>C&amp;ycles:</translation>
    </message>
    <message>
        <source>S&amp;ingle step</source>
        <translation>S&amp;ingle step</translation>
    </message>
    <message>
        <source>Pause after every step; Step runs the next one</source>
        <translation>Pause after every step; Step runs the next one</translation>
    </message>
    <message>
        <source>Lost-step &amp;check at the end</source>
        <translation>Lost-step &amp;check at the end</translation>
    </message>
    <message>
        <source>After the last cycle, the lost-step test on every axis the sequence moved, each referenced on its home switch</source>
        <translation>After the last cycle, the lost-step test on every axis the sequence moved, each referenced on its home switch</translation>
    </message>
    <message>
        <source>&amp;Run</source>
        <translation>&amp;Run</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pause</translation>
    </message>
    <message>
        <source>Pause after the step running now</source>
        <translation>Pause after the step running now</translation>
    </message>
    <message>
        <source>S&amp;tep</source>
        <translation>S&amp;tep</translation>
    </message>
    <message>
        <source>Resu&amp;me</source>
        <translation>Resu&amp;me</translation>
    </message>
    <message>
        <source>&amp;Stop</source>
        <translation>&amp;Stop</translation>
    </message>
    <message>
        <source>Not running.</source>
        <translation>Not running.</translation>
    </message>
</context>
<context>
    <name>stepcom::SequenceRunner</name>
    <message>
        <source>%1: the input did not come within %2 s</source>
        <translation>%1: the input did not come within %2 s</translation>
    </message>
    <message>
        <source>E-STOP: every motor and output stopped; the run ended</source>
        <translation>E-STOP: every motor and output stopped; the run ended</translation>
    </message>
    <message>
        <source>the link was lost (%1): the run ended; the controller goes on with what it was doing</source>
        <translation>the link was lost (%1): the run ended; the controller goes on with what it was doing</translation>
    </message>
    <message>
        <source>the controller restarted (or may have): its positions and references are gone; the run ended</source>
        <translation>the controller restarted (or may have): its positions and references are gone; the run ended</translation>
    </message>
    <message>
        <source>could not read the positions, speeds and homing order (%1): nothing was moved</source>
        <translation>could not read the positions, speeds and homing order (%1): nothing was moved</translation>
    </message>
    <message>
        <source>motor %1 is running</source>
        <translation>motor %1 is running</translation>
    </message>
    <message>
        <source>the run was refused before anything moved: %1</source>
        <translation>the run was refused before anything moved: %1</translation>
    </message>
    <message numerus="yes">
        <source>%n cycle(s) done</source>
        <translation>
            <numerusform>%n cycle done</numerusform>
            <numerusform>%n cycles done</numerusform>
        </translation>
    </message>
    <message>
        <source>stopped: the run was interrupted</source>
        <translation>stopped: the run was interrupted</translation>
    </message>
    <message>
        <source>The motors&apos; own speed or single-move values may not be back: read them before the next run</source>
        <translation>The motors&apos; own speed or single-move values may not be back: read them before the next run</translation>
    </message>
    <message>
        <source>this register map has no homing command for %1</source>
        <translation>this register map has no homing command for %1</translation>
    </message>
    <message>
        <source>could not read what the homing is judged on (%1): nothing was moved</source>
        <translation>could not read what the homing is judged on (%1): nothing was moved</translation>
    </message>
    <message>
        <source>this register map has no command %1</source>
        <translation>this register map has no command %1</translation>
    </message>
    <message>
        <source>the speed could not be written and verified (%1)</source>
        <translation>the speed could not be written and verified (%1)</translation>
    </message>
    <message>
        <source>the controller did not acknowledge %1: the run ended</source>
        <translation>the controller did not acknowledge %1: the run ended</translation>
    </message>
    <message>
        <source>the outputs could not be read back (%1)</source>
        <translation>the outputs could not be read back (%1)</translation>
    </message>
    <message>
        <source>output %1 still reads OFF after its command</source>
        <translation>output %1 still reads OFF after its command</translation>
    </message>
    <message>
        <source>output %1 still reads ON after its command</source>
        <translation>output %1 still reads ON after its command</translation>
    </message>
    <message>
        <source>%1; the outputs the run had switched on read OFF: an E-STOP (or all outputs off) from elsewhere</source>
        <translation>%1; the outputs the run had switched on read OFF: an E-STOP (or all outputs off) from elsewhere</translation>
    </message>
    <message>
        <source>the outputs the run had switched on read OFF: an E-STOP (or all outputs off) from elsewhere</source>
        <translation>the outputs the run had switched on read OFF: an E-STOP (or all outputs off) from elsewhere</translation>
    </message>
</context>
<context>
    <name>stepcom::SequenceStep</name>
    <message>
        <source>home in the set order</source>
        <translation>home in the set order</translation>
    </message>
    <message>
        <source>home %1</source>
        <translation>home %1</translation>
    </message>
    <message>
        <source>move to %1</source>
        <translation>move to %1</translation>
    </message>
    <message>
        <source>move to %1 (%2)</source>
        <translation>move to %1 (%2)</translation>
    </message>
    <message>
        <source>move by %1</source>
        <translation>move by %1</translation>
    </message>
    <message>
        <source>wait for IN%1 ON (at most %2 s)</source>
        <translation>wait for IN%1 ON (at most %2 s)</translation>
    </message>
    <message>
        <source>wait for IN%1 OFF (at most %2 s)</source>
        <translation>wait for IN%1 OFF (at most %2 s)</translation>
    </message>
    <message>
        <source>wait for IN%1 ON</source>
        <translation>wait for IN%1 ON</translation>
    </message>
    <message>
        <source>wait for IN%1 OFF</source>
        <translation>wait for IN%1 OFF</translation>
    </message>
    <message>
        <source>output %1 ON</source>
        <translation>output %1 ON</translation>
    </message>
    <message>
        <source>output %1 OFF</source>
        <translation>output %1 OFF</translation>
    </message>
    <message>
        <source>all outputs ON</source>
        <translation>all outputs ON</translation>
    </message>
    <message>
        <source>all outputs OFF</source>
        <translation>all outputs OFF</translation>
    </message>
    <message>
        <source>dwell %1 ms</source>
        <translation>dwell %1 ms</translation>
    </message>
    <message numerus="yes">
        <source>repeat %n time(s)</source>
        <translation>
            <numerusform>repeat %n time</numerusform>
            <numerusform>repeat %n times</numerusform>
        </translation>
    </message>
    <message>
        <source>speed %1 rpm</source>
        <translation>speed %1 rpm</translation>
    </message>
</context>
<context>
    <name>stepcom::SequenceStepForm</name>
    <message>
        <source>Home</source>
        <translation>Home</translation>
    </message>
    <message>
        <source>Move to</source>
        <translation>Move to</translation>
    </message>
    <message>
        <source>Move by</source>
        <translation>Move by</translation>
    </message>
    <message>
        <source>Wait for an input</source>
        <translation>Wait for an input</translation>
    </message>
    <message>
        <source>Switch output 1</source>
        <translation>Switch output 1</translation>
    </message>
    <message>
        <source>Switch all outputs</source>
        <translation>Switch all outputs</translation>
    </message>
    <message>
        <source>Dwell</source>
        <translation>Dwell</translation>
    </message>
    <message>
        <source>Repeat (a loop)</source>
        <translation>Repeat (a loop)</translation>
    </message>
    <message>
        <source>Set the speed</source>
        <translation>Set the speed</translation>
    </message>
    <message>
        <source>(a position of its own)</source>
        <translation>(a position of its own)</translation>
    </message>
    <message>
        <source>&amp;Step:</source>
        <translation>&amp;Step:</translation>
    </message>
    <message>
        <source>In the set homing order</source>
        <translation>In the set homing order</translation>
    </message>
    <message>
        <source>Motor %1</source>
        <translation>Motor %1</translation>
    </message>
    <message>
        <source>All ON</source>
        <translation>All ON</translation>
    </message>
    <message>
        <source>All OFF</source>
        <translation>All OFF</translation>
    </message>
    <message>
        <source>&amp;Home:</source>
        <translation>&amp;Home:</translation>
    </message>
    <message>
        <source>&amp;Point:</source>
        <translation>&amp;Point:</translation>
    </message>
    <message>
        <source>&amp;Input (IN):</source>
        <translation>&amp;Input (IN):</translation>
    </message>
    <message>
        <source>&amp;Output:</source>
        <translation>&amp;Output:</translation>
    </message>
    <message>
        <source>State:</source>
        <translation>State:</translation>
    </message>
    <message>
        <source>Wait for ON (unticked: for OFF)</source>
        <translation>Wait for ON (unticked: for OFF)</translation>
    </message>
    <message>
        <source>ON (unticked: OFF)</source>
        <translation>ON (unticked: OFF)</translation>
    </message>
    <message>
        <source>&amp;Timeout (0: none):</source>
        <translation>&amp;Timeout (0: none):</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>O&amp;utputs:</source>
        <translation>O&amp;utputs:</translation>
    </message>
    <message>
        <source>&amp;Dwell:</source>
        <translation>&amp;Dwell:</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>&amp;Times:</source>
        <translation>&amp;Times:</translation>
    </message>
    <message>
        <source>Motor %1:</source>
        <translation>Motor %1:</translation>
    </message>
    <message>
        <source>set</source>
        <translation>set</translation>
    </message>
    <message>
        <source>moves</source>
        <translation>moves</translation>
    </message>
    <message>
        <source>The controller switches output 1 alone; all %1 outputs together with &quot;Switch all outputs&quot;.</source>
        <translation>The controller switches output 1 alone; all %1 outputs together with &quot;Switch all outputs&quot;.</translation>
    </message>
</context>
<context>
    <name>stepcom::SerialAdapter</name>
    <message>
        <source>holds received bytes up to its latency timer (16 ms by default), which adds up to 16 ms to every answer; StepCom asks for low latency (1 ms) when it opens the port, and the package&apos;s udev rule sets 1 ms; the kernel&apos;s RS-485 mode is supported by some chips</source>
        <translation>holds received bytes up to its latency timer (16 ms by default), which adds up to 16 ms to every answer; StepCom asks for low latency (1 ms) when it opens the port, and the package&apos;s udev rule sets 1 ms; the kernel&apos;s RS-485 mode is supported by some chips</translation>
    </message>
    <message>
        <source>no latency timer to set; delivers bytes in small USB packets; the driver refuses the kernel&apos;s RS-485 mode (use --rs485 auto with an adapter that switches by itself, or rts)</source>
        <translation>no latency timer to set; delivers bytes in small USB packets; the driver refuses the kernel&apos;s RS-485 mode (use --rs485 auto with an adapter that switches by itself, or rts)</translation>
    </message>
    <message>
        <source>no latency timer to set; RS-485 direction, when the adapter has it, is switched by the chip itself (set in its configuration), not by the kernel&apos;s RS-485 mode</source>
        <translation>no latency timer to set; RS-485 direction, when the adapter has it, is switched by the chip itself (set in its configuration), not by the kernel&apos;s RS-485 mode</translation>
    </message>
    <message>
        <source>copies of the chip are common and the driver may refuse them; no kernel RS-485 mode; bytes come in USB packets</source>
        <translation>copies of the chip are common and the driver may refuse them; no kernel RS-485 mode; bytes come in USB packets</translation>
    </message>
    <message>
        <source>a microcontroller&apos;s own USB serial: the baud set may mean nothing to it and the line&apos;s timing is its firmware&apos;s</source>
        <translation>a microcontroller&apos;s own USB serial: the baud set may mean nothing to it and the line&apos;s timing is its firmware&apos;s</translation>
    </message>
    <message>
        <source>an on-board UART: no USB packets; RS-485 direction through the kernel&apos;s RS-485 mode where the board wires it, else by RTS</source>
        <translation>an on-board UART: no USB packets; RS-485 direction through the kernel&apos;s RS-485 mode where the board wires it, else by RTS</translation>
    </message>
    <message>
        <source>native UART</source>
        <translation>native UART</translation>
    </message>
    <message>
        <source>pseudo-terminal</source>
        <translation>pseudo-terminal</translation>
    </message>
    <message>
        <source>, latency timer %1 ms</source>
        <translation>, latency timer %1 ms</translation>
    </message>
    <message>
        <source>, serial %1</source>
        <translation>, serial %1</translation>
    </message>
</context>
<context>
    <name>stepcom::SerialPorts</name>
    <message>
        <source>S/N %1</source>
        <translation>S/N %1</translation>
    </message>
    <message>
        <source>Stable name: %1</source>
        <translation>Stable name: %1</translation>
    </message>
    <message>
        <source>Adapter: %1</source>
        <translation>Adapter: %1</translation>
    </message>
    <message>
        <source>Manufacturer: %1</source>
        <translation>Manufacturer: %1</translation>
    </message>
    <message>
        <source>Serial number: %1</source>
        <translation>Serial number: %1</translation>
    </message>
    <message>
        <source>USB id: %1:%2</source>
        <translation>USB id: %1:%2</translation>
    </message>
</context>
<context>
    <name>stepcom::SessionBackup</name>
    <message>
        <source>the session ended</source>
        <translation>the session ended</translation>
    </message>
    <message>
        <source>the controller&apos;s settings could not be read: %1</source>
        <translation>the controller&apos;s settings could not be read: %1</translation>
    </message>
</context>
<context>
    <name>stepcom::SessionLog</name>
    <message>
        <source>cannot create the log folder %1</source>
        <translation>cannot create the log folder %1</translation>
    </message>
    <message>
        <source>cannot write the session log %1: %2</source>
        <translation>cannot write the session log %1: %2</translation>
    </message>
</context>
<context>
    <name>stepcom::SimCommandLine</name>
    <message>
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <source>MS</source>
        <translation>MS</translation>
    </message>
    <message>
        <source>SHARE</source>
        <translation>SHARE</translation>
    </message>
    <message>
        <source>Serve Modbus RTU on a new pseudo-terminal (Unix).</source>
        <translation>Serve Modbus RTU on a new pseudo-terminal (Unix).</translation>
    </message>
    <message>
        <source>Make PATH a symlink to the pseudo-terminal.</source>
        <translation>Make PATH a symlink to the pseudo-terminal.</translation>
    </message>
    <message>
        <source>PATH</source>
        <translation>PATH</translation>
    </message>
    <message>
        <source>Answer whatever baud rate the client set (by default a client whose baud differs from register 40213 gets silence, as on a real line).</source>
        <translation>Answer whatever baud rate the client set (by default a client whose baud differs from register 40213 gets silence, as on a real line).</translation>
    </message>
    <message>
        <source>Serve Modbus TCP on [HOST:]PORT (127.0.0.1 unless --listen-any; port 0 picks a free one).</source>
        <translation>Serve Modbus TCP on [HOST:]PORT (127.0.0.1 unless --listen-any; port 0 picks a free one).</translation>
    </message>
    <message>
        <source>[HOST:]PORT</source>
        <translation>[HOST:]PORT</translation>
    </message>
    <message>
        <source>Listen for TCP on every interface.</source>
        <translation>Listen for TCP on every interface.</translation>
    </message>
    <message>
        <source>Device id 1-255 (overrides the saved one).</source>
        <translation>Device id 1-255 (overrides the saved one).</translation>
    </message>
    <message>
        <source>The simulator&apos;s flash: saved parameters are loaded from and saved to FILE.</source>
        <translation>The simulator&apos;s flash: saved parameters are loaded from and saved to FILE.</translation>
    </message>
    <message>
        <source>FILE</source>
        <translation>FILE</translation>
    </message>
    <message>
        <source>Use the register map FILE instead of the built-in one.</source>
        <translation>Use the register map FILE instead of the built-in one.</translation>
    </message>
    <message>
        <source>Add the bytes&apos; time on a line at N baud to every answer.</source>
        <translation>Add the bytes&apos; time on a line at N baud to every answer.</translation>
    </message>
    <message>
        <source>Drop a SHARE (0-1 or %) of the answers.</source>
        <translation>Drop a SHARE (0-1 or %) of the answers.</translation>
    </message>
    <message>
        <source>Break the CRC of a SHARE of the answers.</source>
        <translation>Break the CRC of a SHARE of the answers.</translation>
    </message>
    <message>
        <source>Answer a SHARE of the requests MS later.</source>
        <translation>Answer a SHARE of the requests MS later.</translation>
    </message>
    <message>
        <source>SHARE:MS</source>
        <translation>SHARE:MS</translation>
    </message>
    <message>
        <source>Answer a SHARE of the requests with exception CODE instead.</source>
        <translation>Answer a SHARE of the requests with exception CODE instead.</translation>
    </message>
    <message>
        <source>SHARE:CODE</source>
        <translation>SHARE:CODE</translation>
    </message>
    <message>
        <source>Hang up the port after every N answers (it comes back, see --hangup-pause).</source>
        <translation>Hang up the port after every N answers (it comes back, see --hangup-pause).</translation>
    </message>
    <message>
        <source>How long a hung-up port stays away (default 1000).</source>
        <translation>How long a hung-up port stays away (default 1000).</translation>
    </message>
    <message>
        <source>Seed of the fault dice (default 1).</source>
        <translation>Seed of the fault dice (default 1).</translation>
    </message>
    <message>
        <source>Set an input at start: INn=on|off|pulse (repeatable).</source>
        <translation>Set an input at start: INn=on|off|pulse (repeatable).</translation>
    </message>
    <message>
        <source>INn=STATE</source>
        <translation>INn=STATE</translation>
    </message>
    <message>
        <source>Travel of each axis between its limit switches (default 200).</source>
        <translation>Travel of each axis between its limit switches (default 200).</translation>
    </message>
    <message>
        <source>MM</source>
        <translation>MM</translation>
    </message>
    <message>
        <source>--tcp: &apos;%1&apos; is not [HOST:]PORT</source>
        <translation>--tcp: &apos;%1&apos; is not [HOST:]PORT</translation>
    </message>
    <message>
        <source>--input: &apos;%1&apos; is not INn=on|off|pulse</source>
        <translation>--input: &apos;%1&apos; is not INn=on|off|pulse</translation>
    </message>
    <message>
        <source>--%1: &apos;%2&apos; must be a whole number from %3 to %4</source>
        <translation>--%1: &apos;%2&apos; must be a whole number from %3 to %4</translation>
    </message>
    <message>
        <source>--exception: the code must be 1-255</source>
        <translation>--exception: the code must be 1-255</translation>
    </message>
    <message>
        <source>--travel: &apos;%1&apos; must be a positive distance</source>
        <translation>--travel: &apos;%1&apos; must be a positive distance</translation>
    </message>
    <message>
        <source>Serve Modbus RTU on the serial PORT (e.g. COM10, one end of a com0com pair, or /dev/ttyUSB1) at the device&apos;s baud rate, 8N1.</source>
        <translation>Serve Modbus RTU on the serial PORT (e.g. COM10, one end of a com0com pair, or /dev/ttyUSB1) at the device&apos;s baud rate, 8N1.</translation>
    </message>
    <message>
        <source>PORT</source>
        <translation>PORT</translation>
    </message>
    <message>
        <source>--serial: no port given</source>
        <translation>--serial: no port given</translation>
    </message>
    <message>
        <source>--serial: give either --serial or --pty/--link, not both</source>
        <translation>--serial: give either --serial or --pty/--link, not both</translation>
    </message>
    <message>
        <source>--corrupt-crc works on the pseudo-terminal only, not with --serial</source>
        <translation>--corrupt-crc works on the pseudo-terminal only, not with --serial</translation>
    </message>
    <message>
        <source>Several controllers on the one port, one per id (e.g. 1,2,3 or 1-3); a repeated id is a collision: both answer at once.</source>
        <translation>Several controllers on the one port, one per id (e.g. 1,2,3 or 1-3); a repeated id is a collision: both answer at once.</translation>
    </message>
    <message>
        <source>IDS</source>
        <translation>IDS</translation>
    </message>
    <message>
        <source>--ids: give either --id or --ids, not both</source>
        <translation>--ids: give either --id or --ids, not both</translation>
    </message>
    <message>
        <source>Serve Modbus RTU frames over plain TCP on [HOST:]PORT, as a transparent RS-485/Ethernet converter passes them on (port 0 picks a free one).</source>
        <translation>Serve Modbus RTU frames over plain TCP on [HOST:]PORT, as a transparent RS-485/Ethernet converter passes them on (port 0 picks a free one).</translation>
    </message>
    <message>
        <source>Send every byte the client sends straight back to it first, as a half-duplex USB-RS485 adapter without echo suppression does (pty and --rtu-tcp).</source>
        <translation>Send every byte the client sends straight back to it first, as a half-duplex USB-RS485 adapter without echo suppression does (pty and --rtu-tcp).</translation>
    </message>
    <message>
        <source>--rtu-tcp and --tcp must listen on the same host</source>
        <translation>--rtu-tcp and --tcp must listen on the same host</translation>
    </message>
    <message>
        <source>--echo works on the pseudo-terminal and --rtu-tcp, not with --serial</source>
        <translation>--echo works on the pseudo-terminal and --rtu-tcp, not with --serial</translation>
    </message>
    <message>
        <source>Refuse a read that covers a reserved register (exception 02): only the manual&apos;s listed registers can be read.</source>
        <translation>Refuse a read that covers a reserved register (exception 02): only the manual&apos;s listed registers can be read.</translation>
    </message>
    <message>
        <source>Be a firmware without this listed register (a key or a number such as 40110): reads and writes covering it get exception 02. Repeatable.</source>
        <translation>Be a firmware without this listed register (a key or a number such as 40110): reads and writes covering it get exception 02. Repeatable.</translation>
    </message>
    <message>
        <source>REGISTER</source>
        <translation>REGISTER</translation>
    </message>
    <message>
        <source>The controller&apos;s answer time: its answer leaves MS after a request (default: the map&apos;s, 35, as the manual asks; other firmware answers in 2-20 ms; 0: as fast as it can).</source>
        <translation>The controller&apos;s answer time: its answer leaves MS after a request (default: the map&apos;s, 35, as the manual asks; other firmware answers in 2-20 ms; 0: as fast as it can).</translation>
    </message>
    <message>
        <source>Coil PLC (e.g. 96, save) acts at once but answers MS later, as firmware writing its flash first. Repeatable.</source>
        <translation>Coil PLC (e.g. 96, save) acts at once but answers MS later, as firmware writing its flash first. Repeatable.</translation>
    </message>
    <message>
        <source>PLC:MS</source>
        <translation>PLC:MS</translation>
    </message>
    <message>
        <source>Switch the 24 V off AT seconds after start for OFF seconds: silence, then the saved parameters, positions 0, nothing homed. Repeatable.</source>
        <translation>Switch the 24 V off AT seconds after start for OFF seconds: silence, then the saved parameters, positions 0, nothing homed. Repeatable.</translation>
    </message>
    <message>
        <source>AT:OFF</source>
        <translation>AT:OFF</translation>
    </message>
    <message>
        <source>--power-cycle: &apos;%1&apos; is not AT:OFF (seconds after start, 0-86400, and seconds off, up to 3600; e.g. 10:3)</source>
        <translation>--power-cycle: &apos;%1&apos; is not AT:OFF (seconds after start, 0-86400, and seconds off, up to 3600; e.g. 10:3)</translation>
    </message>
    <message>
        <source>--slow-coil: &apos;%1&apos; is not PLC:MS (a coil number such as 96 and milliseconds 0-600000)</source>
        <translation>--slow-coil: &apos;%1&apos; is not PLC:MS (a coil number such as 96 and milliseconds 0-600000)</translation>
    </message>
    <message>
        <source>--slow-coil: &apos;%1&apos;: %2 is no coil of the map</source>
        <translation>--slow-coil: &apos;%1&apos;: %2 is no coil of the map</translation>
    </message>
    <message>
        <source>Serve a line of N pseudo-terminals: every byte one program sends reaches the others and the controller, as on RS-485 (a master and a listener).</source>
        <translation>Serve a line of N pseudo-terminals: every byte one program sends reaches the others and the controller, as on RS-485 (a master and a listener).</translation>
    </message>
    <message>
        <source>--line: &apos;%1&apos; is not a number of ptys from 1 to 32</source>
        <translation>--line: &apos;%1&apos; is not a number of ptys from 1 to 32</translation>
    </message>
    <message>
        <source>With --line: the parties numbered in LIST (e.g. 2 or 1,3) hear every byte they send back first, as through an adapter without echo suppression.</source>
        <translation>With --line: the parties numbered in LIST (e.g. 2 or 1,3) hear every byte they send back first, as through an adapter without echo suppression.</translation>
    </message>
    <message>
        <source>LIST</source>
        <translation>LIST</translation>
    </message>
    <message>
        <source>--line-echo needs --line N</source>
        <translation>--line-echo needs --line N</translation>
    </message>
    <message>
        <source>--line-echo: &apos;%1&apos; is not a party of the line (1 to %2)</source>
        <translation>--line-echo: &apos;%1&apos; is not a party of the line (1 to %2)</translation>
    </message>
    <message>
        <source>The machine&apos;s mechanics from FILE (format stepcom-sim-machine): motor limits (stalls), backlash, switches, hard stops, wiring.</source>
        <translation>The machine&apos;s mechanics from FILE (format stepcom-sim-machine): motor limits (stalls), backlash, switches, hard stops, wiring.</translation>
    </message>
    <message>
        <source>Keep what really happened (count, rotor, carriage, lost steps, switches) as JSON in FILE, rewritten when it changes (at most every 50 ms).</source>
        <translation>Keep what really happened (count, rotor, carriage, lost steps, switches) as JSON in FILE, rewritten when it changes (at most every 50 ms).</translation>
    </message>
    <message>
        <source>--truth-out: no file given</source>
        <translation>--truth-out: no file given</translation>
    </message>
</context>
<context>
    <name>stepcom::SimConsole</name>
    <message>
        <source>the simulator is not running</source>
        <translation>the simulator is not running</translation>
    </message>
    <message>
        <source>usage: hangup [MS]</source>
        <translation>usage: hangup [MS]</translation>
    </message>
    <message>
        <source>hanging up</source>
        <translation>hanging up</translation>
    </message>
    <message>
        <source>unknown command &apos;%1&apos; (try help)</source>
        <translation>unknown command &apos;%1&apos; (try help)</translation>
    </message>
    <message>
        <source>usage: in N on|off|pulse</source>
        <translation>usage: in N on|off|pulse</translation>
    </message>
    <message>
        <source>usage: in N on|off|pulse, N from 1 to %1</source>
        <translation>usage: in N on|off|pulse, N from 1 to %1</translation>
    </message>
    <message>
        <source>IN%1 is %2</source>
        <translation>IN%1 is %2</translation>
    </message>
    <message>
        <source>on</source>
        <translation>on</translation>
    </message>
    <message>
        <source>off</source>
        <translation>off</translation>
    </message>
    <message>
        <source>usage: get KEY</source>
        <translation>usage: get KEY</translation>
    </message>
    <message>
        <source>%1: no such register</source>
        <translation>%1: no such register</translation>
    </message>
    <message>
        <source>usage: set KEY VALUE</source>
        <translation>usage: set KEY VALUE</translation>
    </message>
    <message>
        <source>usage: do COMMAND</source>
        <translation>usage: do COMMAND</translation>
    </message>
    <message>
        <source>done: %1</source>
        <translation>done: %1</translation>
    </message>
    <message>
        <source>usage: place N MM</source>
        <translation>usage: place N MM</translation>
    </message>
    <message>
        <source>carriage %1 at %2</source>
        <translation>carriage %1 at %2</translation>
    </message>
    <message>
        <source>rtu: %1</source>
        <translation>rtu: %1</translation>
    </message>
    <message>
        <source>(hung up)</source>
        <translation>(hung up)</translation>
    </message>
    <message>
        <source>tcp: %1:%2</source>
        <translation>tcp: %1:%2</translation>
    </message>
    <message>
        <source>requests %1, answers %2 (exceptions %3), dropped %4, bad CRC %5, late %6, wrong baud %7</source>
        <translation>requests %1, answers %2 (exceptions %3), dropped %4, bad CRC %5, late %6, wrong baud %7</translation>
    </message>
    <message>
        <source>Commands:
  status                 motors, inputs, outputs, link and traffic
  in N on|off|pulse      drive input N by hand (pulse: on for 50 ms)
  get KEY                show a register (e.g. get motor1.position)
  set KEY VALUE          write a parameter as a client would (e.g. set motor1.speed 600)
  do COMMAND             run a coil command (e.g. do motor1.move, do estop)
  place N MM             put carriage N at MM on its travel by hand
  hangup [MS]            hang up the port; it comes back after MS
  power-cycle [S] [id N] switch the 24 V off for S seconds (default 3), every
                         controller or the one with id N; it comes back with what
                         was saved, positions 0, nothing homed
  help                   this text
  quit                   end the simulator</source>
        <translation>Commands:
  status                 motors, inputs, outputs, link and traffic
  in N on|off|pulse      drive input N by hand (pulse: on for 50 ms)
  get KEY                show a register (e.g. get motor1.position)
  set KEY VALUE          write a parameter as a client would (e.g. set motor1.speed 600)
  do COMMAND             run a coil command (e.g. do motor1.move, do estop)
  place N MM             put carriage N at MM on its travel by hand
  hangup [MS]            hang up the port; it comes back after MS
  power-cycle [S] [id N] switch the 24 V off for S seconds (default 3), every
                         controller or the one with id N; it comes back with what
                         was saved, positions 0, nothing homed
  help                   this text
  quit                   end the simulator</translation>
    </message>
    <message>
        <source>usage: power-cycle [SECONDS] [id N]</source>
        <translation>usage: power-cycle [SECONDS] [id N]</translation>
    </message>
    <message>
        <source>no controller has id %1</source>
        <translation>no controller has id %1</translation>
    </message>
    <message>
        <source>id %1: 24 V off for %2 s</source>
        <translation>id %1: 24 V off for %2 s</translation>
    </message>
    <message>
        <source>24 V off for %1 s</source>
        <translation>24 V off for %1 s</translation>
    </message>
</context>
<context>
    <name>stepcom::SimDevice</name>
    <message>
        <source>%1: not a writable parameter</source>
        <translation>%1: not a writable parameter</translation>
    </message>
    <message>
        <source>%1: not a command of the map</source>
        <translation>%1: not a command of the map</translation>
    </message>
    <message>
        <source>%1: the device failed</source>
        <translation>%1: the device failed</translation>
    </message>
    <message>
        <source>time %1 ms, mode %2, id %3, %4 baud</source>
        <translation>time %1 ms, mode %2, id %3, %4 baud</translation>
    </message>
    <message>
        <source>motor %1: position %2, %3, carriage at %4 of %5</source>
        <translation>motor %1: position %2, %3, carriage at %4 of %5</translation>
    </message>
    <message>
        <source>running</source>
        <translation>running</translation>
    </message>
    <message>
        <source>idle</source>
        <translation>idle</translation>
    </message>
    <message>
        <source>inputs:%1</source>
        <translation>inputs:%1</translation>
    </message>
    <message>
        <source>outputs:%1</source>
        <translation>outputs:%1</translation>
    </message>
    <message>
        <source>the controller is switched off</source>
        <translation>the controller is switched off</translation>
    </message>
    <message>
        <source>24 V off: power returns in %1 ms</source>
        <translation>24 V off: power returns in %1 ms</translation>
    </message>
</context>
<context>
    <name>stepcom::SimHost</name>
    <message>
        <source>--lacks: %1 is no listed register of the map</source>
        <translation>--lacks: %1 is no listed register of the map</translation>
    </message>
    <message>
        <source>power cycle: 24 V off for %1 s</source>
        <translation>power cycle: 24 V off for %1 s</translation>
    </message>
    <message>
        <source>power cycle: 24 V back on</source>
        <translation>power cycle: 24 V back on</translation>
    </message>
    <message>
        <source>%1: axes.motor%2: the register map has %3 motors</source>
        <translation>%1: axes.motor%2: the register map has %3 motors</translation>
    </message>
</context>
<context>
    <name>stepcom::SimRegisters</name>
    <message>
        <source>%1: not a writable parameter of the map</source>
        <translation>%1: not a writable parameter of the map</translation>
    </message>
</context>
<context>
    <name>stepcom::SimRtuTcpServer</name>
    <message>
        <source>cannot listen for RTU over TCP on %1:%2: %3</source>
        <translation>cannot listen for RTU over TCP on %1:%2: %3</translation>
    </message>
</context>
<context>
    <name>stepcom::SimState</name>
    <message>
        <source>cannot write %1: %2</source>
        <translation>cannot write %1: %2</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>cannot read %1: %2</translation>
    </message>
    <message>
        <source>%1: not JSON (%2)</source>
        <translation>%1: not JSON (%2)</translation>
    </message>
    <message>
        <source>%1: not a simulator state file</source>
        <translation>%1: not a simulator state file</translation>
    </message>
    <message>
        <source>%1: parameter %2 is not a number</source>
        <translation>%1: parameter %2 is not a number</translation>
    </message>
</context>
<context>
    <name>stepcom::SimTcpServer</name>
    <message>
        <source>cannot listen on %1:%2: %3</source>
        <translation>cannot listen on %1:%2: %3</translation>
    </message>
</context>
<context>
    <name>stepcom::SimWorker</name>
    <message>
        <source>RTU server: %1</source>
        <translation>RTU server: %1</translation>
    </message>
    <message>
        <source>cannot open the pseudo-terminal: %1</source>
        <translation>cannot open the pseudo-terminal: %1</translation>
    </message>
    <message>
        <source>cannot re-create the port: %1</source>
        <translation>cannot re-create the port: %1</translation>
    </message>
    <message>
        <source>Modbus RTU on a pseudo-terminal (--pty, --link) is not available on this system (pseudo-terminals are Unix only). Use Modbus TCP instead: stepcom-sim --tcp 5020, then connect StepCom or stepcomctl with --tcp 127.0.0.1:5020; or serve a serial port with --serial, e.g. one end of a com0com virtual port pair (--serial COM10, StepCom on COM11).</source>
        <translation>Modbus RTU on a pseudo-terminal (--pty, --link) is not available on this system (pseudo-terminals are Unix only). Use Modbus TCP instead: stepcom-sim --tcp 5020, then connect StepCom or stepcomctl with --tcp 127.0.0.1:5020; or serve a serial port with --serial, e.g. one end of a com0com virtual port pair (--serial COM10, StepCom on COM11).</translation>
    </message>
    <message>
        <source>cannot open the serial port %1: %2</source>
        <translation>cannot open the serial port %1: %2</translation>
    </message>
</context>
<context>
    <name>stepcom::StatusDock</name>
    <message>
        <source>unknown</source>
        <translation>unknown</translation>
    </message>
    <message>
        <source>Running</source>
        <translation>Running</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Stopped</translation>
    </message>
    <message>
        <source>on</source>
        <translation>on</translation>
    </message>
    <message>
        <source>off</source>
        <translation>off</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Motor %1</source>
        <translation>Motor %1</translation>
    </message>
    <message>
        <source>Inputs and outputs</source>
        <translation>Inputs and outputs</translation>
    </message>
    <message>
        <source>In</source>
        <translation>In</translation>
    </message>
    <message>
        <source>Out</source>
        <translation>Out</translation>
    </message>
    <message>
        <source>IN%1</source>
        <translation>IN%1</translation>
    </message>
    <message>
        <source>OUT%1</source>
        <translation>OUT%1</translation>
    </message>
</context>
<context>
    <name>stepcom::StatusPollRow</name>
    <message>
        <source>unknown</source>
        <translation>unknown</translation>
    </message>
    <message>
        <source>measuring…</source>
        <translation>measuring…</translation>
    </message>
    <message>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <source>Status updates: %1</source>
        <translation>Status updates: %1</translation>
    </message>
    <message>
        <source>&amp;Read the status every:</source>
        <translation>&amp;Read the status every:</translation>
    </message>
    <message>
        <source>How often the status is read. Full rate reads again as soon as a cycle ends; the link decides how fast that is.</source>
        <translation>How often the status is read. Full rate reads again as soon as a cycle ends; the link decides how fast that is.</translation>
    </message>
    <message>
        <source>full rate</source>
        <translation>full rate</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>Achieved:</source>
        <translation>Achieved:</translation>
    </message>
    <message>
        <source>Status updates per second actually achieved by the poller (complete read cycles, not the configured rate)</source>
        <translation>Status updates per second actually achieved by the poller (complete read cycles, not the configured rate)</translation>
    </message>
</context>
<context>
    <name>stepcom::StatusRecorder</name>
    <message>
        <source>Recording to “%1” stopped: %2</source>
        <translation>Recording to “%1” stopped: %2</translation>
    </message>
    <message>
        <source>Cannot write “%1”: %2</source>
        <translation>Cannot write “%1”: %2</translation>
    </message>
    <message>
        <source>Cannot record: no file name given</source>
        <translation>Cannot record: no file name given</translation>
    </message>
    <message>
        <source>Cannot record to “%1”: %2</source>
        <translation>Cannot record to “%1”: %2</translation>
    </message>
</context>
<context>
    <name>stepcom::StepMove</name>
    <message>
        <source>There is no motor %1 (this controller has %2)</source>
        <translation>There is no motor %1 (this controller has %2)</translation>
    </message>
    <message>
        <source>This register map has no single move for motor %1</source>
        <translation>This register map has no single move for motor %1</translation>
    </message>
    <message>
        <source>Motor %1: the distance or position is not a number</source>
        <translation>Motor %1: the distance or position is not a number</translation>
    </message>
    <message>
        <source>Motor %1: a distance cannot be negative</source>
        <translation>Motor %1: a distance cannot be negative</translation>
    </message>
    <message>
        <source>Not connected: nothing was sent</source>
        <translation>Not connected: nothing was sent</translation>
    </message>
    <message>
        <source>A step is still running: wait for it to end</source>
        <translation>A step is still running: wait for it to end</translation>
    </message>
    <message>
        <source>Motor %1: the step uses the single-move distance and direction, and they hold edits that were not written. Write or revert them first.</source>
        <translation>Motor %1: the step uses the single-move distance and direction, and they hold edits that were not written. Write or revert them first.</translation>
    </message>
    <message>
        <source>Motor %1 is jogging: let go first</source>
        <translation>Motor %1 is jogging: let go first</translation>
    </message>
    <message>
        <source>Motor %1 is moving: wait until it ends</source>
        <translation>Motor %1 is moving: wait until it ends</translation>
    </message>
    <message>
        <source>Motor %1: could not read the position and the single-move values (%2): nothing was moved</source>
        <translation>Motor %1: could not read the position and the single-move values (%2): nothing was moved</translation>
    </message>
    <message>
        <source>Motor %1 is running: nothing was moved</source>
        <translation>Motor %1 is running: nothing was moved</translation>
    </message>
    <message>
        <source>Motor %1: %2 %3 is outside the position register&apos;s range</source>
        <translation>Motor %1: %2 %3 is outside the position register&apos;s range</translation>
    </message>
    <message>
        <source>Motor %1 already stands at %2 %3: nothing to move</source>
        <translation>Motor %1 already stands at %2 %3: nothing to move</translation>
    </message>
    <message>
        <source>Motor %1: a move of %2 %3 is more than the single move can do (%4 %3)</source>
        <translation>Motor %1: a move of %2 %3 is more than the single move can do (%4 %3)</translation>
    </message>
    <message>
        <source>the step&apos;s distance and direction could not be written (%1): nothing was moved</source>
        <translation>the step&apos;s distance and direction could not be written (%1): nothing was moved</translation>
    </message>
    <message>
        <source>the single move was not acknowledged: nothing was moved</source>
        <translation>the single move was not acknowledged: nothing was moved</translation>
    </message>
    <message>
        <source>distance %1 %2, direction %3</source>
        <translation>distance %1 %2, direction %3</translation>
    </message>
    <message>
        <source>%1. The single move&apos;s own values (%2) could not be put back: not connected. Write them again once the controller answers.</source>
        <translation>%1. The single move&apos;s own values (%2) could not be put back: not connected. Write them again once the controller answers.</translation>
    </message>
    <message>
        <source>%1. The single move&apos;s own values (%2) could not be put back: %3</source>
        <translation>%1. The single move&apos;s own values (%2) could not be put back: %3</translation>
    </message>
    <message>
        <source>The single move&apos;s own distance and direction are back (verified).</source>
        <translation>The single move&apos;s own distance and direction are back (verified).</translation>
    </message>
</context>
<context>
    <name>stepcom::StepMovePanel</name>
    <message>
        <source>&amp;Step:</source>
        <translation>&amp;Step:</translation>
    </message>
    <message>
        <source>Custom</source>
        <translation>Custom</translation>
    </message>
    <message>
        <source>− Step</source>
        <translation>− Step</translation>
    </message>
    <message>
        <source>+ Step</source>
        <translation>+ Step</translation>
    </message>
    <message>
        <source>Move &amp;to:</source>
        <translation>Move &amp;to:</translation>
    </message>
    <message>
        <source>Move to position</source>
        <translation>Move to position</translation>
    </message>
    <message>
        <source>Steps and move-to use this motor&apos;s single-move distance and direction registers, then write your own values back and verify them. They refuse while those fields hold unwritten edits, and any target beyond the software travel limits.</source>
        <translation>Steps and move-to use this motor&apos;s single-move distance and direction registers, then write your own values back and verify them. They refuse while those fields hold unwritten edits, and any target beyond the software travel limits.</translation>
    </message>
    <message>
        <source>Custom step</source>
        <translation>Custom step</translation>
    </message>
</context>
<context>
    <name>stepcom::SupportBundle</name>
    <message>
        <source>the profile %1 does not exist</source>
        <translation>the profile %1 does not exist</translation>
    </message>
    <message>
        <source>%1 is not a zip file (or cannot be read)</source>
        <translation>%1 is not a zip file (or cannot be read)</translation>
    </message>
    <message>
        <source>the bundle %1 holds no session log</source>
        <translation>the bundle %1 holds no session log</translation>
    </message>
    <message>
        <source>%1 is not a StepCom support bundle</source>
        <translation>%1 is not a StepCom support bundle</translation>
    </message>
    <message>
        <source>%1 holds no %2</source>
        <translation>%1 holds no %2</translation>
    </message>
    <message>
        <source>cannot copy %1 out of %2 into %3</source>
        <translation>cannot copy %1 out of %2 into %3</translation>
    </message>
    <message>
        <source>cannot create the zip file (zip error %1)</source>
        <translation>cannot create the zip file (zip error %1)</translation>
    </message>
    <message>
        <source>cannot write %1 into the bundle</source>
        <translation>cannot write %1 into the bundle</translation>
    </message>
    <message>
        <source>cannot finish the zip file (zip error %1)</source>
        <translation>cannot finish the zip file (zip error %1)</translation>
    </message>
    <message>
        <source>cannot create %1: %2</source>
        <translation>cannot create %1: %2</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>cancelled</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>cannot write %1: %2</translation>
    </message>
</context>
<context>
    <name>stepcom::SupportBundleDialog</name>
    <message>
        <source>Create support bundle</source>
        <translation>Create support bundle</translation>
    </message>
    <message>
        <source>The profile %1 and its checklist</source>
        <translation>The profile %1 and its checklist</translation>
    </message>
    <message>
        <source>No profile is open</source>
        <translation>No profile is open</translation>
    </message>
    <message>
        <source>&amp;Save bundle…</source>
        <translation>&amp;Save bundle…</translation>
    </message>
    <message>
        <source>Profile:</source>
        <translation>Profile:</translation>
    </message>
    <message numerus="yes">
        <source>%n session log(s), %1</source>
        <translation>
            <numerusform>%n session log, %1</numerusform>
            <numerusform>%n session logs, %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Save support bundle</source>
        <translation>Save support bundle</translation>
    </message>
    <message>
        <source>Zip files (*.zip)</source>
        <translation>Zip files (*.zip)</translation>
    </message>
    <message>
        <source>Support bundle written: %1 (%2). It holds:</source>
        <translation>Support bundle written: %1 (%2). It holds:</translation>
    </message>
    <message>
        <source>The support bundle was not written: %1</source>
        <translation>The support bundle was not written: %1</translation>
    </message>
    <message>
        <source>Session logs of the last days:</source>
        <translation>Session logs of the last days:</translation>
    </message>
    <message>
        <source>One .zip file to send to support: the session logs (every frame of every connection), the profile and its checklist, the commissioning report of the machine, StepCom&apos;s settings (there are no passwords in them), the versions of StepCom, Qt and the system, and the serial adapters seen. A README inside lists it all.</source>
        <translation>One .zip file to send to support: the session logs (every frame of every connection), the profile and its checklist, the commissioning report of the machine, StepCom&apos;s settings (there are no passwords in them), the versions of StepCom, Qt and the system, and the serial adapters seen. A README inside lists it all.</translation>
    </message>
    <message>
        <source>Report:</source>
        <translation>Report:</translation>
    </message>
    <message numerus="yes">
        <source>id(s) %1 as last read</source>
        <translation>
            <numerusform>id %1 as last read</numerusform>
            <numerusform>ids %1 as last read</numerusform>
        </translation>
    </message>
    <message>
        <source>the profile %1</source>
        <translation>the profile %1</translation>
    </message>
    <message>
        <source>The support bundle was cancelled: nothing was written.</source>
        <translation>The support bundle was cancelled: nothing was written.</translation>
    </message>
    <message>
        <source>The commissioning report of the machine</source>
        <translation>The commissioning report of the machine</translation>
    </message>
    <message>
        <source>None: no device&apos;s settings were read in this session and no profile goes in</source>
        <translation>None: no device&apos;s settings were read in this session and no profile goes in</translation>
    </message>
</context>
<context>
    <name>stepcom::SwitchReference</name>
    <message>
        <source>the home switch (IN%1) did not come ON within %2 %3 toward it</source>
        <translation>the home switch (IN%1) did not come ON within %2 %3 toward it</translation>
    </message>
    <message>
        <source>the home switch (IN%1) stayed ON %2 %3 away from it</source>
        <translation>the home switch (IN%1) stayed ON %2 %3 away from it</translation>
    </message>
    <message>
        <source>the home switch (IN%1) did not come ON again within %2 creep moves</source>
        <translation>the home switch (IN%1) did not come ON again within %2 creep moves</translation>
    </message>
</context>
<context>
    <name>stepcom::TrafficModel</name>
    <message>
        <source>Time</source>
        <translation>Time</translation>
    </message>
    <message>
        <source>Dir</source>
        <translation>Dir</translation>
    </message>
    <message>
        <source>Bytes (hex)</source>
        <translation>Bytes (hex)</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>Meaning</translation>
    </message>
</context>
<context>
    <name>stepcom::TrafficView</name>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pause</translation>
    </message>
    <message>
        <source>C&amp;lear</source>
        <translation>C&amp;lear</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Copy</translation>
    </message>
    <message>
        <source>Save traffic log</source>
        <translation>Save traffic log</translation>
    </message>
    <message>
        <source>Text files (*.txt *.log)</source>
        <translation>Text files (*.txt *.log)</translation>
    </message>
    <message>
        <source>Could not save %1: %2</source>
        <translation>Could not save %1: %2</translation>
    </message>
    <message>
        <source>Open log folder</source>
        <translation>Open log folder</translation>
    </message>
    <message>
        <source>Hold the rows still to read them; frames are still kept</source>
        <translation>Hold the rows still to read them; frames are still kept</translation>
    </message>
    <message>
        <source>Polls</source>
        <translation>Polls</translation>
    </message>
    <message>
        <source>The live status poll: several frames a second</source>
        <translation>The live status poll: several frames a second</translation>
    </message>
    <message>
        <source>Reads</source>
        <translation>Reads</translation>
    </message>
    <message>
        <source>Writes</source>
        <translation>Writes</translation>
    </message>
    <message>
        <source>Commands</source>
        <translation>Commands</translation>
    </message>
    <message>
        <source>Errors</source>
        <translation>Errors</translation>
    </message>
    <message>
        <source>Search (text, key or bytes)</source>
        <translation>Search (text, key or bytes)</translation>
    </message>
    <message>
        <source>Search</source>
        <translation>Search</translation>
    </message>
    <message>
        <source>Copy the selected rows (all rows shown when none are selected)</source>
        <translation>Copy the selected rows (all rows shown when none are selected)</translation>
    </message>
    <message>
        <source>&amp;Save log…</source>
        <translation>&amp;Save log…</translation>
    </message>
    <message>
        <source>Save the rows shown to a file</source>
        <translation>Save the rows shown to a file</translation>
    </message>
    <message>
        <source>Open log &amp;folder</source>
        <translation>Open log &amp;folder</translation>
    </message>
    <message>
        <source>The session log files: every frame of every connection, with date and time (%1)</source>
        <translation>The session log files: every frame of every connection, with date and time (%1)</translation>
    </message>
    <message>
        <source>Cannot create the log folder %1.</source>
        <translation>Cannot create the log folder %1.</translation>
    </message>
    <message>
        <source>No file manager opened %1. The session log files are there.</source>
        <translation>No file manager opened %1. The session log files are there.</translation>
    </message>
    <message>
        <source>Earlier lines</source>
        <translation>Earlier lines</translation>
    </message>
    <message>
        <source>Show the lines of the replayed log before the first one here (scrolling to the top does it too)</source>
        <translation>Show the lines of the replayed log before the first one here (scrolling to the top does it too)</translation>
    </message>
</context>
<context>
    <name>stepcom::Translators</name>
    <message>
        <source>Language of the program: en or zh_CN (default: the system&apos;s, from LANGUAGE, LC_ALL, LC_MESSAGES or LANG).</source>
        <translation>Language of the program: en or zh_CN (default: the system&apos;s, from LANGUAGE, LC_ALL, LC_MESSAGES or LANG).</translation>
    </message>
    <message>
        <source>language</source>
        <translation>language</translation>
    </message>
    <message>
        <source>unknown language &apos;%1&apos; (known: %2)</source>
        <translation>unknown language &apos;%1&apos; (known: %2)</translation>
    </message>
    <message>
        <source>, </source>
        <comment>between the items of a list</comment>
        <translation>, </translation>
    </message>
</context>
<context>
    <name>stepcom::TravelCalibration</name>
    <message>
        <source>commanded distance</source>
        <translation>commanded distance</translation>
    </message>
    <message>
        <source>measured distance</source>
        <translation>measured distance</translation>
    </message>
    <message>
        <source>the %1 must be more than 0 %2, found %3</source>
        <translation>the %1 must be more than 0 %2, found %3</translation>
    </message>
    <message>
        <source>not a number</source>
        <translation>not a number</translation>
    </message>
    <message>
        <source>the %1 %2 %3 is not a distance on a machine</source>
        <translation>the %1 %2 %3 is not a distance on a machine</translation>
    </message>
    <message>
        <source>the current pitch (%1) cannot be corrected: %2</source>
        <translation>the current pitch (%1) cannot be corrected: %2</translation>
    </message>
    <message>
        <source>it must be more than 0</source>
        <translation>it must be more than 0</translation>
    </message>
    <message>
        <source>the distances must be at least 0.001 %1</source>
        <translation>the distances must be at least 0.001 %1</translation>
    </message>
    <message>
        <source>%1 %2 measured for %3 %2 commanded is off by a factor of %4: that is not a calibration error. Check the microsteps (driver DIP switches and register), the step angle and the pitch, then measure again</source>
        <translation>%1 %2 measured for %3 %2 commanded is off by a factor of %4: that is not a calibration error. Check the microsteps (driver DIP switches and register), the step angle and the pitch, then measure again</translation>
    </message>
    <message>
        <source>the corrected pitch would be %1 %2: %3</source>
        <translation>the corrected pitch would be %1 %2: %3</translation>
    </message>
</context>
<context>
    <name>stepcom::TravelLimits</name>
    <message>
        <source>motor %1: this register map has no such axis</source>
        <translation>motor %1: this register map has no such axis</translation>
    </message>
    <message>
        <source>motor %1, software travel limit %2: %3</source>
        <translation>motor %1, software travel limit %2: %3</translation>
    </message>
    <message>
        <source>motor %1: the software travel limit min (%2) must be below max (%3)</source>
        <translation>motor %1: the software travel limit min (%2) must be below max (%3)</translation>
    </message>
    <message>
        <source>motor %1: %2 is not a position</source>
        <translation>motor %1: %2 is not a position</translation>
    </message>
    <message>
        <source>motor %1: %2 is beyond the software travel limit max %3</source>
        <translation>motor %1: %2 is beyond the software travel limit max %3</translation>
    </message>
    <message>
        <source>motor %1: %2 is beyond the software travel limit min %3</source>
        <translation>motor %1: %2 is beyond the software travel limit min %3</translation>
    </message>
    <message>
        <source>motor %1 is at %2, at or beyond its software travel limit max %3: it may only jog toward −</source>
        <translation>motor %1 is at %2, at or beyond its software travel limit max %3: it may only jog toward −</translation>
    </message>
    <message>
        <source>motor %1 is at %2, at or beyond its software travel limit min %3: it may only jog toward +</source>
        <translation>motor %1 is at %2, at or beyond its software travel limit min %3: it may only jog toward +</translation>
    </message>
    <message>
        <source>motor %1 reached its software travel limit max %2 (polled at %3): stop</source>
        <translation>motor %1 reached its software travel limit max %2 (polled at %3): stop</translation>
    </message>
    <message>
        <source>motor %1 reached its software travel limit min %2 (polled at %3): stop</source>
        <translation>motor %1 reached its software travel limit min %2 (polled at %3): stop</translation>
    </message>
    <message>
        <source>up to %1 beyond a software limit at %2/s (reaction %3 ms: poll %4 ms, read %5 ms, stop %6 ms)</source>
        <translation>up to %1 beyond a software limit at %2/s (reaction %3 ms: poll %4 ms, read %5 ms, stop %6 ms)</translation>
    </message>
    <message>
        <source>braking %1 ms included</source>
        <translation>braking %1 ms included</translation>
    </message>
    <message>
        <source>&quot;travelLimits&quot; must be an object {&quot;motor1&quot;: {&quot;min&quot;: …, &quot;max&quot;: …}}</source>
        <translation>&quot;travelLimits&quot; must be an object {&quot;motor1&quot;: {&quot;min&quot;: …, &quot;max&quot;: …}}</translation>
    </message>
    <message>
        <source>&quot;travelLimits&quot;: unknown axis &quot;%1&quot; (this map has motor1 .. motor%2)</source>
        <translation>&quot;travelLimits&quot;: unknown axis &quot;%1&quot; (this map has motor1 .. motor%2)</translation>
    </message>
    <message>
        <source>&quot;travelLimits&quot;: &quot;%1&quot; must be an object {&quot;min&quot;: …, &quot;max&quot;: …}</source>
        <translation>&quot;travelLimits&quot;: &quot;%1&quot; must be an object {&quot;min&quot;: …, &quot;max&quot;: …}</translation>
    </message>
    <message>
        <source>&quot;travelLimits&quot;: &quot;%1&quot;: unknown field &quot;%2&quot; (allowed: min, max)</source>
        <translation>&quot;travelLimits&quot;: &quot;%1&quot;: unknown field &quot;%2&quot; (allowed: min, max)</translation>
    </message>
    <message>
        <source>&quot;travelLimits&quot;: &quot;%1&quot;: &quot;%2&quot; must be a number</source>
        <translation>&quot;travelLimits&quot;: &quot;%1&quot;: &quot;%2&quot; must be a number</translation>
    </message>
    <message>
        <source>&quot;travelLimits&quot;: &quot;%1&quot; sets neither min nor max</source>
        <translation>&quot;travelLimits&quot;: &quot;%1&quot; sets neither min nor max</translation>
    </message>
</context>
<context>
    <name>stepcom::TravelLimitsEditor</name>
    <message>
        <source>The saved software travel limits were not used: %1</source>
        <translation>The saved software travel limits were not used: %1</translation>
    </message>
    <message>
        <source>How far a jog can overrun a limit is worked out once the speed and pitch are read and the link has answered.</source>
        <translation>How far a jog can overrun a limit is worked out once the speed and pitch are read and the link has answered.</translation>
    </message>
    <message>
        <source>A hold-to-move jog can run past a limit by %1.</source>
        <translation>A hold-to-move jog can run past a limit by %1.</translation>
    </message>
    <message>
        <source>Software travel limits</source>
        <translation>Software travel limits</translation>
    </message>
    <message>
        <source>Motor %1</source>
        <translation>Motor %1</translation>
    </message>
    <message>
        <source>Min</source>
        <translation>Min</translation>
    </message>
    <message>
        <source>Max</source>
        <translation>Max</translation>
    </message>
    <message>
        <source>Apply limits</source>
        <translation>Apply limits</translation>
    </message>
    <message>
        <source>StepCom&apos;s limits, not the controller&apos;s: a step or move-to beyond them is refused and a jog is stopped when the polled position crosses them. Saved with the connection settings and in profiles. If the link dies during a jog, only the limit switches stop the axis.</source>
        <translation>StepCom&apos;s limits, not the controller&apos;s: a step or move-to beyond them is refused and a jog is stopped when the polled position crosses them. Saved with the connection settings and in profiles. If the link dies during a jog, only the limit switches stop the axis.</translation>
    </message>
    <message>
        <source>StepCom&apos;s limits, not the controller&apos;s: if the link dies during a jog, only the limit switches stop the axis.</source>
        <translation>StepCom&apos;s limits, not the controller&apos;s: if the link dies during a jog, only the limit switches stop the axis.</translation>
    </message>
</context>
<context>
    <name>stepcom::TruthWriter</name>
    <message>
        <source>--truth-out: %1: %2</source>
        <translation>--truth-out: %1: %2</translation>
    </message>
</context>
<context>
    <name>stepcom::ValueCheck</name>
    <message>
        <source>%1 – %2</source>
        <translation>%1 – %2</translation>
    </message>
    <message>
        <source>%1: enter a value (%2).</source>
        <translation>%1: enter a value (%2).</translation>
    </message>
    <message>
        <source>%1: “%2” is not a number. Allowed: %3.</source>
        <translation>%1: “%2” is not a number. Allowed: %3.</translation>
    </message>
    <message numerus="yes">
        <source>%1: at most %n decimal(s). Allowed: %2.</source>
        <translation>
            <numerusform>%1: at most %n decimal. Allowed: %2.</numerusform>
            <numerusform>%1: at most %n decimals. Allowed: %2.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: %2 is outside the allowed range %3.</source>
        <translation>%1: %2 is outside the allowed range %3.</translation>
    </message>
    <message>
        <source>%1: “%2” is not one of %3.</source>
        <translation>%1: “%2” is not one of %3.</translation>
    </message>
</context>
<context>
    <name>stepcom::WiringCheck</name>
    <message>
        <source>positive limit</source>
        <translation>positive limit</translation>
    </message>
    <message>
        <source>negative limit</source>
        <translation>negative limit</translation>
    </message>
    <message>
        <source>home input</source>
        <translation>home input</translation>
    </message>
    <message>
        <source>single trigger</source>
        <translation>single trigger</translation>
    </message>
    <message>
        <source>forward/reverse trigger</source>
        <translation>forward/reverse trigger</translation>
    </message>
    <message>
        <source>hold-to-jog</source>
        <translation>hold-to-jog</translation>
    </message>
    <message>
        <source>fixed-distance trigger</source>
        <translation>fixed-distance trigger</translation>
    </message>
    <message>
        <source>as motor 1&apos;s positive limit</source>
        <translation>as motor 1&apos;s positive limit</translation>
    </message>
    <message>
        <source>as motor 1&apos;s negative limit</source>
        <translation>as motor 1&apos;s negative limit</translation>
    </message>
    <message>
        <source>to start motor 1</source>
        <translation>to start motor 1</translation>
    </message>
    <message>
        <source>to stop motor 1 (the next start keeps the direction)</source>
        <translation>to stop motor 1 (the next start keeps the direction)</translation>
    </message>
    <message>
        <source>to stop motor 1 (the next start reverses)</source>
        <translation>to stop motor 1 (the next start reverses)</translation>
    </message>
    <message>
        <source>to stop motor 1 (the next start goes forward)</source>
        <translation>to stop motor 1 (the next start goes forward)</translation>
    </message>
    <message>
        <source>to run motor 1 forward</source>
        <translation>to run motor 1 forward</translation>
    </message>
    <message>
        <source>to run motor 1 in reverse</source>
        <translation>to run motor 1 in reverse</translation>
    </message>
    <message>
        <source>to jog motor 1 forward while it is on</source>
        <translation>to jog motor 1 forward while it is on</translation>
    </message>
    <message>
        <source>to jog motor 1 in reverse while it is on</source>
        <translation>to jog motor 1 in reverse while it is on</translation>
    </message>
    <message>
        <source>to move motor 1 forward by its move distance</source>
        <translation>to move motor 1 forward by its move distance</translation>
    </message>
    <message>
        <source>to move motor 1 in reverse by its move distance</source>
        <translation>to move motor 1 in reverse by its move distance</translation>
    </message>
    <message>
        <source>Motor %1: %2 is both the positive and the negative limit</source>
        <translation>Motor %1: %2 is both the positive and the negative limit</translation>
    </message>
    <message>
        <source>Motor %1: only the positive limit is set (%2); nothing stops the motor at the negative end</source>
        <translation>Motor %1: only the positive limit is set (%2); nothing stops the motor at the negative end</translation>
    </message>
    <message>
        <source>Motor %1: only the negative limit is set (%2); nothing stops the motor at the positive end</source>
        <translation>Motor %1: only the negative limit is set (%2); nothing stops the motor at the positive end</translation>
    </message>
    <message>
        <source>Motor %1: no home input; homing runs in reverse until the negative limit or a stop and does not zero the position</source>
        <translation>Motor %1: no home input; homing runs in reverse until the negative limit or a stop and does not zero the position</translation>
    </message>
    <message>
        <source>Motor %1: the home input %2 is the positive limit, but homing runs in reverse, away from it; use the negative limit&apos;s input</source>
        <translation>Motor %1: the home input %2 is the positive limit, but homing runs in reverse, away from it; use the negative limit&apos;s input</translation>
    </message>
    <message>
        <source>Motor %1: the home input %2 is neither of its limits; usually the home input is the negative limit (%3)</source>
        <translation>Motor %1: the home input %2 is neither of its limits; usually the home input is the negative limit (%3)</translation>
    </message>
    <message>
        <source>none</source>
        <translation>none</translation>
    </message>
    <message>
        <source>motor %1 %2</source>
        <translation>motor %1 %2</translation>
    </message>
    <message>
        <source>%1 is wired to more than one motor (%2): its switch acts on all of them</source>
        <translation>%1 is wired to more than one motor (%2): its switch acts on all of them</translation>
    </message>
    <message>
        <source>Motor %1: %2 is set as the %3, but system mode %4 (%5) ignores the limit settings</source>
        <translation>Motor %1: %2 is set as the %3, but system mode %4 (%5) ignores the limit settings</translation>
    </message>
    <message>
        <source>Motor %1: %2 is set as the %3, but system mode %4 (%5) ignores the limit settings and uses %2 %6</source>
        <translation>Motor %1: %2 is set as the %3, but system mode %4 (%5) ignores the limit settings and uses %2 %6</translation>
    </message>
</context>
<context>
    <name>stepcom::WiringWarnings</name>
    <message>
        <source>The wiring is not known yet: connect and read the controller.</source>
        <translation>The wiring is not known yet: connect and read the controller.</translation>
    </message>
    <message>
        <source>No suspicious wiring found.</source>
        <translation>No suspicious wiring found.</translation>
    </message>
</context>
<context>
    <name>stepcom::WriteChangesDialog</name>
    <message>
        <source>Write changes to the controller</source>
        <translation>Write changes to the controller</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Register</source>
        <translation>Register</translation>
    </message>
    <message>
        <source>Controller holds</source>
        <translation>Controller holds</translation>
    </message>
    <message>
        <source>New value</source>
        <translation>New value</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unknown</translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) will be written and then read back to verify. They stay in the controller&apos;s RAM until you save to flash.</source>
        <translation>
            <numerusform>%n parameter will be written and then read back to verify. It stays in the controller&apos;s RAM until you save to flash.</numerusform>
            <numerusform>%n parameters will be written and then read back to verify. They stay in the controller&apos;s RAM until you save to flash.</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Write</source>
        <translation>&amp;Write</translation>
    </message>
    <message>
        <source>The pages flag problems in these values:</source>
        <translation>The pages flag problems in these values:</translation>
    </message>
    <message>
        <source>&amp;Write anyway</source>
        <translation>&amp;Write anyway</translation>
    </message>
</context>
<context>
    <name>stepcom::WriteReview</name>
    <message>
        <source>Arc: %1</source>
        <translation>Arc: %1</translation>
    </message>
    <message>
        <source>Line: %1</source>
        <translation>Line: %1</translation>
    </message>
    <message>
        <source>System mode %1 “%2” changes what the inputs IN1-IN4 do, at once, and ignores the limit settings: no limit input stops a motor then.</source>
        <translation>System mode %1 “%2” changes what the inputs IN1-IN4 do, at once, and ignores the limit settings: no limit input stops a motor then.</translation>
    </message>
    <message>
        <source>System mode %1 “%2” changes what the inputs IN1-IN4 do, at once.</source>
        <translation>System mode %1 “%2” changes what the inputs IN1-IN4 do, at once.</translation>
    </message>
</context>
<context>
    <name>stepcom::XYPlot</name>
    <message>
        <source>Cannot write the picture “%1”.</source>
        <translation>Cannot write the picture “%1”.</translation>
    </message>
</context>
<context>
    <name>stepcom::XyPicture</name>
    <message>
        <source>start, middle and end point are on one line</source>
        <translation>start, middle and end point are on one line</translation>
    </message>
    <message>
        <source>the start point is the centre</source>
        <translation>the start point is the centre</translation>
    </message>
    <message>
        <source>X: motor 1</source>
        <translation>X: motor 1</translation>
    </message>
    <message>
        <source>Y: motor 2</source>
        <translation>Y: motor 2</translation>
    </message>
    <message>
        <source>on</source>
        <translation>on</translation>
    </message>
    <message>
        <source>off</source>
        <translation>off</translation>
    </message>
    <message>
        <source>Arc</source>
        <translation>Arc</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>Line</translation>
    </message>
    <message>
        <source>● start   ○ end   dashed: interpolation off</source>
        <translation>● start   ○ end   dashed: interpolation off</translation>
    </message>
</context>
<context>
    <name>stepcomctl</name>
    <message>
        <source>What to do.</source>
        <translation>What to do.</translation>
    </message>
    <message>
        <source>list every parameter and command of the register map</source>
        <translation>list every parameter and command of the register map</translation>
    </message>
    <message>
        <source>read parameters (all when none are named)</source>
        <translation>read parameters (all when none are named)</translation>
    </message>
    <message>
        <source>write parameters in engineering units, then verify</source>
        <translation>write parameters in engineering units, then verify</translation>
    </message>
    <message>
        <source>pulse a command coil (e.g. motor1.stop, estop)</source>
        <translation>pulse a command coil (e.g. motor1.stop, estop)</translation>
    </message>
    <message>
        <source>Commands:</source>
        <translation>Commands:</translation>
    </message>
    <message>
        <source>Read and write the parameters of a 2-axis stepper controller over Modbus RTU/TCP.</source>
        <translation>Read and write the parameters of a 2-axis stepper controller over Modbus RTU/TCP.</translation>
    </message>
    <message>
        <source>compare two profiles, no controller needed; exit 0
same, 1 different, 2 bad file</source>
        <translation>compare two profiles, no controller needed; exit 0
same, 1 different, 2 bad file</translation>
    </message>
    <message>
        <source>write the profile&apos;s values that differ, after showing
them and asking (--yes skips the question), then verify;
--include-link also writes device id and baud,
--save-to-flash saves afterwards; the settings it
replaces are saved as a backup first (--no-backup)</source>
        <translation>write the profile&apos;s values that differ, after showing
them and asking (--yes skips the question), then verify;
--include-link also writes device id and baud,
--save-to-flash saves afterwards; the settings it
replaces are saved as a backup first (--no-backup)</translation>
    </message>
    <message>
        <source>pulse a motion command and wait until it ends; print
how it ended (--json), exit 0 only when done or referenced</source>
        <translation>pulse a motion command and wait until it ends; print
how it ended (--json), exit 0 only when done or referenced</translation>
    </message>
    <message>
        <source>move motorN by D or to X (axis units) with its single
move; its own distance and direction are put back and
verified; exit 0 only when it arrived</source>
        <translation>move motorN by D or to X (axis units) with its single
move; its own distance and direction are put back and
verified; exit 0 only when it arrived</translation>
    </message>
    <message>
        <source>give the one controller at --id (default 1, as it
leaves the factory) the device id N and check it
answers there; refuses when N is taken or two
controllers answer at --id</source>
        <translation>give the one controller at --id (default 1, as it
leaves the factory) the device id N and check it
answers there; refuses when N is taken or two
controllers answer at --id</translation>
    </message>
    <message>
        <source>print the live status as one JSON object per line,
until --count samples or Ctrl-C (--interval MS);
with --id 1,2,3 each device in turn, one line a
sample keyed by its id (--json for JSON)</source>
        <translation>print the live status as one JSON object per line,
until --count samples or Ctrl-C (--interval MS);
with --id 1,2,3 each device in turn, one line a
sample keyed by its id (--json for JSON)</translation>
    </message>
    <message>
        <source>read every setting and save it as a profile file
(--name, --notes; --include-link adds id and baud);
into a folder: one file per --id, &quot;id2 NAME DATE.json&quot;</source>
        <translation>read every setting and save it as a profile file
(--name, --notes; --include-link adds id and baud);
into a folder: one file per --id, &quot;id2 NAME DATE.json&quot;</translation>
    </message>
    <message>
        <source>write the commissioning report (--name, --notes,
--lang en|zh_CN; --from PROFILE: from a profile
file and its checklist, no controller needed;
--id 1,2,3: every controller in one document)</source>
        <translation>write the commissioning report (--name, --notes,
--lang en|zh_CN; --from PROFILE: from a profile
file and its checklist, no controller needed;
--id 1,2,3: every controller in one document)</translation>
    </message>
    <message>
        <source>replay a session log (--log FILE or the window&apos;s):
--events, --at TIME [--json], --diff T1 T2; no
controller needed</source>
        <translation>replay a session log (--log FILE or the window&apos;s):
--events, --at TIME [--json], --diff T1 T2; no
controller needed</translation>
    </message>
    <message>
        <source>make a support bundle: the session logs of the last
--days N, --profile FILE, the settings, versions, OS
and serial adapters, the machine report (of the
profile, and of the controllers given with --port,
--tcp or --sim and --id), with a README inside</source>
        <translation>make a support bundle: the session logs of the last
--days N, --profile FILE, the settings, versions, OS
and serial adapters, the machine report (of the
profile, and of the controllers given with --port,
--tcp or --sim and --id), with a README inside</translation>
    </message>
    <message>
        <source>success: done, written and verified; diff: the same;
scan: found; move, command --wait: arrived</source>
        <translation>success: done, written and verified; diff: the same;
scan: found; move, command --wait: arrived</translation>
    </message>
    <message>
        <source>Exit codes (every command):</source>
        <translation>Exit codes (every command):</translation>
    </message>
    <message>
        <source>Usage:</source>
        <translation>Usage:</translation>
    </message>
    <message>
        <source>The link and the other options: stepcomctl --help</source>
        <translation>The link and the other options: stepcomctl --help</translation>
    </message>
    <message>
        <source>compare the controller with a profile (exit 0 the
same, 1 different, 3 link or device error)</source>
        <translation>compare the controller with a profile (exit 0 the
same, 1 different, 3 link or device error)</translation>
    </message>
    <message>
        <source>One command&apos;s help: stepcomctl NAME --help</source>
        <translation>One command&apos;s help: stepcomctl NAME --help</translation>
    </message>
    <message>
        <source>find every controller on the line (--port, --rtu-tcp or
--sim; --tcp: ids only) at --bauds, --parity and --ids; a table
(or --json) of id, baud, parity and what answered;
--probe-timeout MS for slow controllers; exit 0 found,
1 none, 2 usage, 3 link error</source>
        <translation>find every controller on the line (--port, --rtu-tcp or
--sim; --tcp: ids only) at --bauds, --parity and --ids; a table
(or --json) of id, baud, parity and what answered;
--probe-timeout MS for slow controllers; exit 0 found,
1 none, 2 usage, 3 link error</translation>
    </message>
    <message>
        <source>list the serial ports: stable by-id name, adapter
(vendor, product, serial number) and whether another
program holds it; no controller needed</source>
        <translation>list the serial ports: stable by-id name, adapter
(vendor, product, serial number) and whether another
program holds it; no controller needed</translation>
    </message>
    <message>
        <source>the built-in simulator starts from the factory again (id 1, 9600 baud)</source>
        <translation>the built-in simulator starts from the factory again (id 1, 9600 baud)</translation>
    </message>
    <message>
        <source>hear a line another master (a PLC, an HMI) drives, never
sending a byte: each request paired with its answer and
decoded by the map, a line each as heard (--json), until
Ctrl-C or --seconds N; a summary of frames, pairs, CRC
errors and answer times on stderr (--port, --baud,
--parity; --log FILE keeps it as a session log)</source>
        <translation>hear a line another master (a PLC, an HMI) drives, never
sending a byte: each request paired with its answer and
decoded by the map, a line each as heard (--json), until
Ctrl-C or --seconds N; a summary of frames, pairs, CRC
errors and answer times on stderr (--port, --baud,
--parity; --log FILE keeps it as a session log)</translation>
    </message>
    <message>
        <source>not done: a link or device error, a value not
verified, a file or backup that could not be
written; diff: different; scan: none found; move,
command --wait: stopped elsewhere or not known;
lost-steps: lost or not known; a proof stopped
(Ctrl-C, E-STOP, end of input)</source>
        <translation>not done: a link or device error, a value not
verified, a file or backup that could not be
written; diff: different; scan: none found; move,
command --wait: stopped elsewhere or not known;
lost-steps: lost or not known; a proof stopped
(Ctrl-C, E-STOP, end of input)</translation>
    </message>
    <message>
        <source>nothing was done: a usage or validation error, a bad
file, a write the window asks about without --yes,
an apply not confirmed, a proof refused</source>
        <translation>nothing was done: a usage or validation error, a bad
file, a write the window asks about without --yes,
an apply not confirmed, a proof refused</translation>
    </message>
    <message>
        <source>diff, scan: a link or device error (their 1 is an
answer); run: the link lost, the controller
restarted, a command not taken; lost-steps,
margin, backlash: the link lost, a restart, a
read or move that failed</source>
        <translation>diff, scan: a link or device error (their 1 is an
answer); run: the link lost, the controller
restarted, a command not taken; lost-steps,
margin, backlash: the link lost, a restart, a
read or move that failed</translation>
    </message>
    <message>
        <source>prove the axis keeps its steps: the count against the
home switch before and after --cycles K moves of
--distance D out fast and back slowly, and the other
way (docs/proving.md); shown and asked first (--yes);
exit 0 kept, 1 lost, not known or stopped, 2 refused,
3 link, restart or device</source>
        <translation>prove the axis keeps its steps: the count against the
home switch before and after --cycles K moves of
--distance D out fast and back slowly, and the other
way (docs/proving.md); shown and asked first (--yes);
exit 0 kept, 1 lost, not known or stopped, 2 refused,
3 link, restart or device</translation>
    </message>
    <message>
        <source>the lost-step test at each speed --from .. --to in
--step (--accel: the acceleration), lowest first, up
to the first loss; recommends 75 % of the highest kept
and writes it only with --apply; exit 0 searched, 1
stopped or nothing kept to apply, 2 refused, 3 link</source>
        <translation>the lost-step test at each speed --from .. --to in
--step (--accel: the acceleration), lowest first, up
to the first loss; recommends 75 % of the highest kept
and writes it only with --apply; exit 0 searched, 1
stopped or nothing kept to apply, 2 refused, 3 link</translation>
    </message>
    <message>
        <source>the lost motion on reversal with a dial gauge: moves of
--distance D, each followed by &apos;gauge (mm)?&apos; on stderr
and a reading from stdin; exit 0 measured, 1 stopped
(end of input), 2 refused, 3 link</source>
        <translation>the lost motion on reversal with a dial gauge: moves of
--distance D, each followed by &apos;gauge (mm)?&apos; on stderr
and a reading from stdin; exit 0 measured, 1 stopped
(end of input), 2 refused, 3 link</translation>
    </message>
    <message>
        <source>run a machine cycle (a .stepseq file: home, moves, waits
for inputs, outputs, dwells, repeats; docs/sequence.md)
--cycles N times, after showing it and asking (--yes);
each step a line on stderr (--json: JSON lines); Ctrl-C
stops the motors; --check-steps: then the lost-step test
on every axis it moved; exit 0 done (and kept), 1
stopped by the machine (timeout, limit, E-STOP), Ctrl-C
or steps lost, 2 bad file, 3 link, restart or device</source>
        <translation>run a machine cycle (a .stepseq file: home, moves, waits
for inputs, outputs, dwells, repeats; docs/sequence.md)
--cycles N times, after showing it and asking (--yes);
each step a line on stderr (--json: JSON lines); Ctrl-C
stops the motors; --check-steps: then the lost-step test
on every axis it moved; exit 0 done (and kept), 1
stopped by the machine (timeout, limit, E-STOP), Ctrl-C
or steps lost, 2 bad file, 3 link, restart or device</translation>
    </message>
</context>
</TS>
