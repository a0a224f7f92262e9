#!/usr/bin/python3
"""A PLC as the master of a line: pymodbus's RTU client polls and writes a StepCom controller
as a machine's PLC would, for the listen tests and the longer bench.
    plc_master.py PORT BAUD SECONDS
Each request it made is printed as it was answered, one line each:
    read ADDRESS COUNT | write ADDRESS VALUE | write32 ADDRESS VALUE | coil ADDRESS | error TEXT
then "done N" with the number of requests."""
import sys
import time

from pymodbus.client import ModbusSerialClient

port, baud, seconds = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
client = ModbusSerialClient(port=port, baudrate=baud, parity="N", stopbits=1, timeout=1)
if not client.connect():
    print("error cannot open", port, flush=True)
    sys.exit(1)
end = time.monotonic() + seconds
n = 0
speed = 100
while time.monotonic() < end:
    step = n % 6
    if step in (0, 2, 4):
        # The status a PLC polls: the first motor's settings, then the positions.
        address, count = (0, 10) if step != 2 else (107, 4)
        r = client.read_holding_registers(address, count, slave=1)
        print("error read" if r.isError() else "read %d %d" % (address, count), flush=True)
    elif step == 1:
        speed = 100 + (speed + 37) % 2800
        r = client.write_register(5, speed, slave=1)
        print("error write" if r.isError() else "write 5 %d" % speed, flush=True)
    elif step == 3:
        pitch = 100 + n % 5000  # 1.00 .. 50.99 mm, low word first
        r = client.write_registers(16, [pitch & 0xFFFF, pitch >> 16], slave=1)
        print("error write32" if r.isError() else "write32 16 %d" % pitch, flush=True)
    else:
        r = client.write_coil(4, True, slave=1)  # motor1.stop
        print("error coil" if r.isError() else "coil 4", flush=True)
    n += 1
client.close()
print("done", n, flush=True)
