#!/usr/bin/env python3
"""Stream telemetry with asyncio while commands run.

usage: telemetry_async.py [SPEC] [--count N]

SPEC is the GCU's link ("tcp:192.168.144.108", "udp:192.168.144.108", "serial:/dev/ttyUSB0");
without it, a simulated GCU is started in this process. Prints one line per reply (N of them)
while a task zooms in to 5x and turns the gimbal.
"""

import argparse
import asyncio
import sys

import xfgcu
import xfgcu.aio


async def drive(gimbal: xfgcu.aio.AsyncGimbal) -> None:
    """Commands and control from a task of their own, while the stream runs."""
    print(f"zoom-to: {(await gimbal.send('zoom_to', factor=5.0)).status}")
    print(f"head-lock: {(await gimbal.send('head_lock')).status}")
    for _ in range(20):
        await gimbal.set_rates(0.0, 0.0, 30.0)  # deg/s; refreshed within the rate watchdog
        await asyncio.sleep(0.05)
    await gimbal.set_rates(0.0, 0.0, 0.0)


async def stream(spec: str, count: int) -> int:
    async with xfgcu.aio.connect(spec) as gimbal:
        task = asyncio.create_task(drive(gimbal))
        n = 0
        async for t in gimbal.telemetry_stream():
            print(
                f"{n:4d} {t.mode_name or t.gimbal_mode:<12} roll {t.cam_roll:7.2f} pitch {t.cam_pitch:7.2f} "
                f"yaw {t.cam_yaw:7.2f} deg  zoom {t.zoom_cam1:.1f}x"
            )
            n += 1
            if n >= count:
                break
        await task
        health = await gimbal.health()
        print(f"link {health.link}, {health.replies} replies, {health.replies_missing} missing/s")
    return 0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("spec", nargs="?", help="the GCU's link spec (default: a simulated GCU)")
    parser.add_argument("--count", type=int, default=100, help="replies to print (default 100)")
    args = parser.parse_args()
    if args.spec:
        return asyncio.run(stream(args.spec, args.count))
    with xfgcu.Simulator("udp:127.0.0.1:0") as sim:
        return asyncio.run(stream(sim.spec, args.count))


if __name__ == "__main__":
    sys.exit(main())
