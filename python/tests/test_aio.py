"""xfgcu.aio: the same API, async, on the asyncio loop."""

from __future__ import annotations

import asyncio
from typing import Any, Dict, List

import xfgcu
import xfgcu.aio


def test_async_send_and_stream(sim: xfgcu.Simulator) -> None:
    async def main() -> None:
        async with xfgcu.aio.connect(sim.spec) as g:
            r = await g.send("shutter")
            assert r.status == "ok"
            got: List[Dict[str, Any]] = []
            async for t in g.telemetry_stream():
                got.append(t)
                if len(got) == 5:
                    break
            assert all(isinstance(t, xfgcu.Telemetry) and t.direction == "gcu" for t in got)
            assert (await g.health()).link == "up"
            assert (await g.telemetry()) is not None

    asyncio.run(asyncio.wait_for(main(), 20))
    assert sim.stats()["photos"] == 1


def test_async_concurrent_commands_and_control(udp_sim: xfgcu.Simulator) -> None:
    async def main() -> None:
        g = await xfgcu.aio.connect(udp_sim.spec)
        try:
            # commands queue in the client and run one after the other, the protocol's way
            results = await asyncio.gather(g.send("zoom-in"), g.send("zoom-stop"), g.send("euler"))
            assert [r.status for r in results] == ["ok", "ok", "ok"]
            await g.set_angles(0.0, -10.0, 0.0)
            await g.clear_control()
        finally:
            await g.close()

    asyncio.run(asyncio.wait_for(main(), 20))


def test_stream_ends_on_close(sim: xfgcu.Simulator) -> None:
    async def main() -> None:
        g = await xfgcu.aio.connect(sim.spec)
        got: List[Dict[str, Any]] = []

        async def consume() -> None:
            async for t in g.telemetry_stream():
                got.append(t)

        task = asyncio.create_task(consume())
        await asyncio.sleep(0.2)
        await g.close()
        await asyncio.wait_for(task, 2)  # ends with the gimbal, never hangs
        assert got

    asyncio.run(asyncio.wait_for(main(), 20))
