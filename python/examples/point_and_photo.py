#!/usr/bin/env python3
"""Point the gimbal and take a photo.

usage: point_and_photo.py [SPEC] [--pitch DEG] [--yaw DEG]

SPEC is the GCU's link ("tcp:192.168.144.108", "udp:192.168.144.108", "serial:/dev/ttyUSB0");
without it, a simulated GCU is started in this process.
"""

import argparse
import sys
import time

import xfgcu


def point_and_photo(spec: str, pitch: float, yaw: float) -> int:
    with xfgcu.connect(spec) as gimbal:
        t = gimbal.telemetry()
        print(f"connected to {gimbal.description}, protocol {gimbal.protocol}: mode {t.mode_name if t else '?'}")
        try:
            gimbal.send("euler", check=True)  # Euler angles: set_angles() gives absolute pitch and yaw
        except xfgcu.CommandFailed as failed:
            print(f"euler: {failed.result.status}", file=sys.stderr)
            return 1
        deadline = time.monotonic() + 10.0
        for t in gimbal.telemetry_stream(timeout=1.0):  # every reply, as it comes
            gimbal.set_angles(0.0, pitch, yaw)  # refreshed: a mode change drops a setpoint
            if abs(t.cam_pitch - pitch) < 0.5 and abs((t.cam_yaw - yaw + 180) % 360 - 180) < 0.5:
                break
            if time.monotonic() > deadline:
                print("the gimbal did not reach the angles", file=sys.stderr)
                return 1
        print(f"pointing at pitch {t.cam_pitch:.2f} yaw {t.cam_yaw:.2f} {xfgcu.Telemetry.unit('cam_yaw')}")
        result = gimbal.send("shutter")
        packets = f"{result.packets} packet{'s' if result.packets != 1 else ''}"
        print(f"photo: {result.status} ({packets}, {result.elapsed_ms} ms)")
        return 0 if result.ok else 1


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("spec", nargs="?", help="the GCU's link spec (default: a simulated GCU)")
    parser.add_argument("--pitch", type=float, default=-30.0)
    parser.add_argument("--yaw", type=float, default=45.0)
    args = parser.parse_args()
    if args.spec:
        return point_and_photo(args.spec, args.pitch, args.yaw)
    with xfgcu.Simulator("udp:127.0.0.1:0") as sim:
        rc = point_and_photo(sim.spec, args.pitch, args.yaw)
        print(f"simulator: {sim.stats()['photos']} photo(s) taken")
        return rc


if __name__ == "__main__":
    sys.exit(main())
