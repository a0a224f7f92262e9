<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>stepcom::BusScanner</name>
    <message>
        <source>no baud rate to try</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>scan finished</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>scan id %1 at %2 baud</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>answered (register 40001 = %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>answered with an exception: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stepcom::CtlOptions</name>
    <message>
        <source>Serial port of the controller (e.g. /dev/ttyUSB0, COM3).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>path</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Modbus TCP gateway or simulator, HOST[:PORT] (port 502).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>host:port</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use the built-in simulated controller.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Baud rate: 4800, 9600, 19200 or 38400 (default 9600).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parity: none, even or odd (default none).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>parity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop bits: 1 or 2 (default 1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>n</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device id 1-255 (default 1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Answer timeout in ms (default 500).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Retries after a timeout (default 2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Register map file to use instead of the built-in one.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine-readable JSON output.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the Modbus traffic on standard error.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Do not ask: needed for commands that destroy settings.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>After writing, save the parameters to flash.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>monitor: number of samples (default: until stopped).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>monitor: ms between samples (default: as fast as the link allows).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>give only one of --port, --tcp and --sim</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--tcp: &apos;%1&apos; is not HOST[:PORT]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--baud: &apos;%1&apos; is not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--parity: &apos;%1&apos; is not none, even or odd</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--stop-bits: &apos;%1&apos; is not 1 or 2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--id: &apos;%1&apos; is not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--timeout: &apos;%1&apos; is not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--retries: &apos;%1&apos; is not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--count: &apos;%1&apos; is not a positive number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--interval: &apos;%1&apos; is not a number of ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no command given (params, read, write, command)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stepcom::CtlRunner</name>
    <message>
        <source>unknown command &apos;%1&apos; (params, read, write, command)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no controller given: use --port PATH, --tcp HOST[:PORT] or --sim</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot connect to %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot start the built-in simulator: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown parameter &apos;%1&apos; (see: stepcomctl params)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is a command and cannot be read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>write needs KEY=VALUE arguments</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not KEY=VALUE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is a command: use &apos;stepcomctl command %1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is read-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>nothing was written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(written, verified)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not written: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this map has no save_to_flash command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>saved to flash</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>command needs exactly one command name (see: stepcomctl params)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is a parameter, not a command: use read or write</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown command &apos;%1&apos; (see: stepcomctl params)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 destroys settings (%2); add --yes if you mean it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: done</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stepcom::DeviceClient</name>
    <message>
        <source>nothing readable among the parameters asked for</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>read block %1/%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown parameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is read-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is given twice</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stepcom::DeviceSession</name>
    <message>
        <source>Cannot connect: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connected to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Link lost: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot start the built-in simulator: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>disconnected by the user</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Read %n parameter(s) in %1 request(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Wrote and verified %n parameter(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Unknown command %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>E-STOP: not connected, nothing was sent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>emergency stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>E-STOP sent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The controller answers at %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The controller does not answer with the new settings: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stepcom::FaultInjector</name>
    <message>
        <source>&apos;%1&apos; is not a share between 0 and 1 (or 0%-100%)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos;: expected SHARE:NUMBER, e.g. 0.1:500</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stepcom::LinkSettings</name>
    <message>
        <source>device id %1 is outside 1-255</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>timeout %1 ms is outside 20-60000 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>retries %1 is outside 0-10</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no host given</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TCP port %1 is outside 1-65535</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no serial port given</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>baud %1 is not one of 4800, 9600, 19200, 38400</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stop bits must be 1 or 2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stepcom::Modbus</name>
    <message>
        <source>illegal function</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>illegal data address</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>illegal data value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>server device failure</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>acknowledge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>server device busy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>exception %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stepcom::ModbusLink</name>
    <message>
        <source>no connection to %1 within %2 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reconnecting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>serial port %1 does not exist (is the adapter plugged in?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no permission to open %1: add your user to the group that owns it (on Debian and Ubuntu: sudo usermod -aG dialout $USER), then log out and in again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connecting to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot open %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connected to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connection closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the port reported an error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>link lost: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>link closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>disconnected: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: not done, %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: not connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: cancelled%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: could not send: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: answer carried %2 registers, %3 were asked for</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the controller refused: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: answers had a bad checksum (CRC)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: no answer within %2 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> -- the controller may have acted on it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the port stopped responding (no answer and no timeout from the driver)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stepcom::Parameter</name>
    <message>
        <source>%1: %2 is not one of %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 is out of range (%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: no value given</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%1: &apos;%2&apos; has more than %n decimal(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is far too large</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 is far too large</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%1: %2 has more than %n decimal(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
</context>
<context>
    <name>stepcom::ParameterField</name>
    <message>
        <source>Not read from the controller yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The controller holds this value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edited, not written yet (the controller holds %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edited, not written yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stepcom::ParameterStore</name>
    <message>
        <source>unknown parameter %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is read-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the controller holds %1 instead</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not written: an earlier write failed</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stepcom::SimCommandLine</name>
    <message>
        <source>N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MS</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SHARE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Serve Modbus RTU on a new pseudo-terminal (Unix).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Make PATH a symlink to the pseudo-terminal.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PATH</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Answer whatever baud rate the client set (by default a client whose baud differs from register 40213 gets silence, as on a real line).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Serve Modbus TCP on [HOST:]PORT (127.0.0.1 unless --listen-any; port 0 picks a free one).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>[HOST:]PORT</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Listen for TCP on every interface.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refuse reads of reserved registers (exception 02) instead of reading 0.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device id 1-255 (overrides the saved one).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The simulator&apos;s flash: saved parameters are loaded from and saved to FILE.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>FILE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use the register map FILE instead of the built-in one.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Answer no sooner than MS after a request (default: the map&apos;s, 35).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add the bytes&apos; time on a line at N baud to every answer.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drop a SHARE (0-1 or %) of the answers.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Break the CRC of a SHARE of the answers.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Answer a SHARE of the requests MS later.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SHARE:MS</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Answer a SHARE of the requests with exception CODE instead.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SHARE:CODE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hang up the port after every N answers (it comes back, see --hangup-pause).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How long a hung-up port stays away (default 1000).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Seed of the fault dice (default 1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set an input at start: INn=on|off|pulse (repeatable).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>INn=STATE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Travel of each axis between its limit switches (default 200).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--tcp: &apos;%1&apos; is not [HOST:]PORT</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--input: &apos;%1&apos; is not INn=on|off|pulse</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--%1: &apos;%2&apos; must be a whole number from %3 to %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--exception: the code must be 1-255</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--travel: &apos;%1&apos; must be a positive distance</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stepcom::SimConsole</name>
    <message>
        <source>Commands:
  status                 motors, inputs, outputs, link and traffic
  in N on|off|pulse      drive input N by hand (pulse: on for 50 ms)
  get KEY                show a register (e.g. get motor1.position)
  set KEY VALUE          write a parameter as a client would (e.g. set motor1.speed 600)
  do COMMAND             run a coil command (e.g. do motor1.move, do estop)
  place N MM             put carriage N at MM on its travel by hand
  hangup [MS]            hang up the port; it comes back after MS
  help                   this text
  quit                   end the simulator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the simulator is not running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>usage: hangup [MS]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>hanging up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown command &apos;%1&apos; (try help)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>usage: in N on|off|pulse</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>usage: in N on|off|pulse, N from 1 to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>IN%1 is %2</source>
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
    <message>
        <source>usage: get KEY</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: no such register</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>usage: set KEY VALUE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>usage: do COMMAND</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>done: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>usage: place N MM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>carriage %1 at %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rtu: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(hung up)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>tcp: %1:%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>requests %1, answers %2 (exceptions %3), dropped %4, bad CRC %5, late %6, wrong baud %7</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stepcom::SimDevice</name>
    <message>
        <source>%1: not a writable parameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: not a command of the map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the device failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>time %1 ms, mode %2, id %3, %4 baud</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>motor %1: position %2, %3, carriage at %4 of %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>idle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>inputs:%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>outputs:%1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stepcom::SimRegisters</name>
    <message>
        <source>%1: not a writable parameter of the map</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stepcom::SimState</name>
    <message>
        <source>cannot write %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: not JSON (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: not a simulator state file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: parameter %2 is not a number</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stepcom::SimTcpServer</name>
    <message>
        <source>cannot listen on %1:%2: %3</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stepcom::SimWorker</name>
    <message>
        <source>RTU server: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot open the pseudo-terminal: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Modbus RTU on a pseudo-terminal is not available on this system; use --tcp</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot re-create the port: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stepcom::WriteJob</name>
    <message>
        <source>could not reopen the port at the new baud: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: wrote %2 but the controller holds %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: wrote %2 but could not read it back</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>stepcomctl</name>
    <message>
        <source>Read and write the parameters of a 2-axis stepper controller over Modbus RTU/TCP.

Commands:
  params                 list every parameter and command of the register map
  read [KEY...]          read parameters (all when none are named)
  write KEY=VALUE...     write parameters in engineering units, then verify
  command NAME           pulse a command coil (e.g. motor1.stop, estop)

Exit codes: 0 success, 1 link or device error, 2 usage or validation error.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What to do.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
