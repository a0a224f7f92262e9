#!/usr/bin/python3
"""A second, independent Modbus RTU controller for StepCom's tests: pymodbus's own RTU server
(Debian python3-pymodbus with python3-serial-asyncio) on a serial port or pty, holding the
controller's registers with plausible values. It answers in a few milliseconds, as fast
firmware does, and an FC05/FC06 answer is the request's exact copy, as the protocol says.

    pymodbus_controller.py PORT [--unit 1]
"""
import argparse
import logging
import sys

from pymodbus.datastore import (ModbusSequentialDataBlock, ModbusServerContext,
                                ModbusSlaveContext)
from pymodbus.server import StartSerialServer
from pymodbus.transaction import ModbusRtuFramer


def registers():
    """Holding registers 40001-40320 (protocol addresses 0-319) as a controller leaves the
    factory: 1.8 degree motors, 8 microsteps, 300 rpm, 5 mm pitch, id 1 at 9600."""
    hr = [0] * 320
    for base in (0, 10):  # motor 1 at 40001, motor 2 at 40011
        hr[base + 0] = 180   # step angle x100
        hr[base + 1] = 8     # microsteps
        hr[base + 2] = 400   # start frequency
        hr[base + 3] = 4000  # acceleration frequency
        hr[base + 4] = 0     # direction
        hr[base + 5] = 300   # speed, rpm
        hr[base + 6] = 500   # pitch x100, low word
        hr[base + 8] = 1000  # move distance x100, low word
    hr[80], hr[81], hr[82] = 1, 2, 2  # motor 1 limits and home inputs
    hr[83], hr[84], hr[85] = 3, 4, 4
    hr[176], hr[177] = 1, 2           # homing order
    hr[200] = 100                     # arc speed
    hr[210] = 100                     # line speed
    hr[211] = 1                       # device id
    hr[212] = 9600                    # baud
    return hr


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("port")
    parser.add_argument("--unit", type=int, default=1)
    args = parser.parse_args()
    logging.basicConfig(level=logging.ERROR, stream=sys.stderr)
    # ModbusSequentialDataBlock(0, ...) with zero_mode: protocol address n is entry n.
    store = ModbusSlaveContext(hr=ModbusSequentialDataBlock(0, registers()),
                               co=ModbusSequentialDataBlock(0, [0] * 128), zero_mode=True)
    context = ModbusServerContext(slaves={args.unit: store}, single=False)
    print("pymodbus controller on", args.port, flush=True)
    StartSerialServer(context=context, framer=ModbusRtuFramer, port=args.port, baudrate=9600)


if __name__ == "__main__":
    main()
