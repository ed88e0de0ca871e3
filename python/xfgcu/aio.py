"""The client on the asyncio loop: ``gimbal = await xfgcu.aio.connect(spec)`` (or
``async with xfgcu.aio.connect(spec) as gimbal``) gives the API of xfgcu.Gimbal with async
methods. The client still runs in its own thread; blocking calls (connecting, send) run in the
loop's default executor, and telemetry reaches the loop with call_soon_threadsafe."""

from __future__ import annotations

import asyncio
import functools
from typing import Any, AsyncIterator, Callable, Dict, Generator, Optional

from .client import Gimbal, Result, TelemetryCallback

__all__ = ["connect", "AsyncGimbal"]


class AsyncGimbal:
    """xfgcu.Gimbal with async methods (see there for each)."""

    def __init__(self, gimbal: Gimbal) -> None:
        self.gimbal = gimbal  #: the synchronous Gimbal underneath
        self.description = gimbal.description

    async def _call(self, fn: Any, *args: Any, **kwargs: Any) -> Any:
        loop = asyncio.get_running_loop()
        return await loop.run_in_executor(None, functools.partial(fn, *args, **kwargs))

    async def send(self, name: str, *, force: bool = False, timeout: Optional[float] = None, **args: Any) -> Result:
        return await self._call(self.gimbal.send, name, force=force, timeout=timeout, **args)  # type: ignore[no-any-return]

    async def submit(self, name: str, *, force: bool = False, **args: Any) -> int:
        return self.gimbal.submit(name, force=force, **args)

    async def result(self, ident: int, name: str = "") -> Optional[Result]:
        return self.gimbal.result(ident, name)

    async def wait_reply(self, timeout: float = 1.0) -> bool:
        return await self._call(self.gimbal.wait_reply, timeout)  # type: ignore[no-any-return]

    def on_telemetry(self, callback: TelemetryCallback) -> Callable[[], None]:
        """As Gimbal.on_telemetry (the callback runs on the client's thread, not the loop)."""
        return self.gimbal.on_telemetry(callback)

    async def set_rates(self, roll: float = 0.0, pitch: float = 0.0, yaw: float = 0.0) -> str:
        return self.gimbal.set_rates(roll, pitch, yaw)

    async def set_angles(self, roll: float = 0.0, pitch: float = 0.0, yaw: float = 0.0) -> str:
        return self.gimbal.set_angles(roll, pitch, yaw)

    async def clear_control(self) -> None:
        self.gimbal.clear_control()

    async def set_carrier(self, roll: float, pitch: float, yaw: float, **rest: float) -> None:
        self.gimbal.set_carrier(roll, pitch, yaw, **rest)

    async def set_gnss(self, latitude: float, longitude: float, altitude: float, **rest: Any) -> None:
        self.gimbal.set_gnss(latitude, longitude, altitude, **rest)

    async def telemetry(self) -> Optional[Dict[str, Any]]:
        return self.gimbal.telemetry()

    async def health(self) -> Dict[str, Any]:
        return self.gimbal.health()

    async def cancel_all(self) -> None:
        self.gimbal.cancel_all()

    async def telemetry_stream(self, maxsize: int = 256) -> AsyncIterator[Dict[str, Any]]:
        """Every reply's telemetry (as telemetry() gives it), as it arrives; it ends when the
        gimbal is closed. When the consumer falls more than ``maxsize`` replies behind, the
        oldest are dropped."""
        loop = asyncio.get_running_loop()
        queue: "asyncio.Queue[Optional[Dict[str, Any]]]" = asyncio.Queue(maxsize)

        def put(t: Optional[Dict[str, Any]]) -> None:
            if queue.full():
                queue.get_nowait()
            queue.put_nowait(t)

        def deliver(t: Optional[Dict[str, Any]]) -> None:  # on the client's thread (None: closed)
            try:
                loop.call_soon_threadsafe(put, t)
            except RuntimeError:  # the loop has closed; the generator goes with it
                pass

        def closed() -> None:
            deliver(None)

        remove = self.gimbal.on_telemetry(deliver)
        self.gimbal._closers.append(closed)
        try:
            while True:
                t = await queue.get()
                if t is None:
                    return
                yield t
        finally:
            remove()
            if closed in self.gimbal._closers:
                self.gimbal._closers.remove(closed)

    async def close(self) -> None:
        await self._call(self.gimbal.close)

    async def __aenter__(self) -> "AsyncGimbal":
        return self

    async def __aexit__(self, *exc: object) -> None:
        await self.close()


class _Connecting:
    """What connect() returns: await it, or use it in ``async with``."""

    def __init__(self, spec: str, config: Dict[str, Any]) -> None:
        self._spec = spec
        self._config = config
        self._gimbal: Optional[AsyncGimbal] = None

    async def _open(self) -> AsyncGimbal:
        loop = asyncio.get_running_loop()
        future = loop.run_in_executor(None, functools.partial(Gimbal, self._spec, **self._config))
        try:
            gimbal = await asyncio.shield(future)
        except asyncio.CancelledError:
            # the connection goes on in the executor: close what it makes, or it would live on
            future.add_done_callback(lambda f: f.exception() is None and f.result().close())
            raise
        return AsyncGimbal(gimbal)

    def __await__(self) -> Generator[Any, None, AsyncGimbal]:
        return self._open().__await__()

    async def __aenter__(self) -> AsyncGimbal:
        self._gimbal = await self._open()
        return self._gimbal

    async def __aexit__(self, *exc: object) -> None:
        if self._gimbal is not None:
            await self._gimbal.close()


def connect(spec: str, **config: Any) -> _Connecting:
    """xfgcu.connect() on the asyncio loop: ``await connect(spec)`` or ``async with connect(spec)
    as gimbal``."""
    return _Connecting(spec, config)
