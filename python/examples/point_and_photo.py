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
        print(f"connected to {gimbal.description}: mode {t['units']['mode'] if t else '?'}")
        result = gimbal.send("euler")  # Euler angles: set_angles() gives absolute pitch and yaw
        if not result.ok:
            print(f"euler: {result.status}", file=sys.stderr)
            return 1
        deadline = time.monotonic() + 10.0
        while time.monotonic() < deadline:
            gimbal.set_angles(0.0, pitch, yaw)  # refreshed: the client sends the latest each packet
            u = gimbal.telemetry()["units"]  # type: ignore[index]
            if abs(u["cam_pitch_deg"] - pitch) < 0.5 and abs((u["cam_yaw_deg"] - yaw + 180) % 360 - 180) < 0.5:
                break
            time.sleep(0.05)
        else:
            print("the gimbal did not reach the angles", file=sys.stderr)
            return 1
        print(f"pointing at pitch {u['cam_pitch_deg']:.2f} yaw {u['cam_yaw_deg']:.2f} deg")
        result = gimbal.send("shutter")
        print(f"photo: {result.status} ({result.packets} packets, {result.elapsed_ms} ms)")
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
