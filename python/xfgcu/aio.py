"""The client on the asyncio loop: ``gimbal = await xfgcu.aio.connect(spec)`` (or
``async with xfgcu.aio.connect(spec) as gimbal``) gives the API of xfgcu.Gimbal with async
methods. The client still runs in its own thread; blocking calls (connecting, send, close) run
in the loop's default executor, and telemetry reaches the loop with call_soon_threadsafe.
Arguments are checked as Gimbal checks them, and after close() every call but close() raises
ClosedError."""

from __future__ import annotations

import asyncio
import functools
from typing import Any, AsyncIterator, Callable, Dict, Generator, Optional, TypeVar, Union

from . import _check
from .client import Gimbal, TelemetryCallback
from .results import ControlStatus, Health, Result, Telemetry

__all__ = ["connect", "AsyncGimbal"]

_R = TypeVar("_R")


async def _in_executor(fn: Callable[..., _R], *args: Any, **kwargs: Any) -> _R:
    loop = asyncio.get_running_loop()
    return await loop.run_in_executor(None, functools.partial(fn, *args, **kwargs))


class AsyncGimbal:
    """xfgcu.Gimbal with async methods (see there for each)."""

    def __init__(self, gimbal: Gimbal) -> None:
        self.gimbal = gimbal  #: the synchronous Gimbal underneath
        self.description = gimbal.description

    async def send(
        self,
        name: str,
        *,
        force: bool = False,
        timeout: Optional[float] = None,
        check: Optional[bool] = None,
        **args: Any,
    ) -> Result:
        self.gimbal._check_open()  # at once, not in the executor: the same error as every other call
        return await _in_executor(self.gimbal.send, name, force=force, timeout=timeout, check=check, **args)

    async def submit(self, name: str, *, force: bool = False, **args: Any) -> int:
        return self.gimbal.submit(name, force=force, **args)

    async def result(self, ident: int, name: str = "") -> Optional[Result]:
        return self.gimbal.result(ident, name)

    async def wait_reply(self, timeout: float = 1.0) -> bool:
        self.gimbal._check_open()
        return await _in_executor(self.gimbal.wait_reply, timeout)

    def on_telemetry(self, callback: TelemetryCallback) -> Callable[[], None]:
        """As Gimbal.on_telemetry (the callback runs on the client's thread, not the loop)."""
        return self.gimbal.on_telemetry(callback)

    async def set_rates(self, roll: float = 0.0, pitch: float = 0.0, yaw: float = 0.0) -> ControlStatus:
        return self.gimbal.set_rates(roll, pitch, yaw)

    async def set_angles(self, roll: float = 0.0, pitch: float = 0.0, yaw: float = 0.0) -> ControlStatus:
        return self.gimbal.set_angles(roll, pitch, yaw)

    async def set_main_camera(self, camera: int) -> None:
        self.gimbal.set_main_camera(camera)

    async def clear_control(self) -> None:
        self.gimbal.clear_control()

    async def set_carrier(self, roll: float, pitch: float, yaw: float, **rest: float) -> None:
        self.gimbal.set_carrier(roll, pitch, yaw, **rest)

    async def set_gnss(self, latitude: float, longitude: float, altitude: float, **rest: Any) -> None:
        self.gimbal.set_gnss(latitude, longitude, altitude, **rest)

    async def telemetry(self) -> Optional[Telemetry]:
        return self.gimbal.telemetry()

    async def health(self) -> Health:
        return self.gimbal.health()

    @property
    def protocol(self) -> Optional[int]:
        """As Gimbal.protocol: the version byte the GCU answers."""
        return self.gimbal.protocol

    @property
    def gcu_protocol(self) -> Optional[int]:
        """As Gimbal.gcu_protocol: the version byte of the GCU's replies."""
        return self.gimbal.gcu_protocol

    async def cancel_all(self) -> None:
        self.gimbal.cancel_all()

    def telemetry_stream(self, maxsize: int = 256) -> AsyncIterator[Telemetry]:
        """Every reply's telemetry (as telemetry() gives it), as it arrives; it ends when the
        gimbal is closed. When the consumer falls more than ``maxsize`` replies behind, the
        oldest are dropped. (A timeout: asyncio.wait_for around each step.)"""
        self.gimbal._check_open()
        size = _check.integer("telemetry_stream", "maxsize", maxsize, 1, 2**20)
        return self._stream(size)

    async def _stream(self, maxsize: int) -> AsyncIterator[Telemetry]:
        loop = asyncio.get_running_loop()
        queue: "asyncio.Queue[Optional[Telemetry]]" = asyncio.Queue(maxsize)

        def put(t: Optional[Telemetry]) -> None:
            if queue.full():
                queue.get_nowait()
            queue.put_nowait(t)

        def deliver(t: Optional[Telemetry]) -> None:  # on the client's thread (None: closed)
            try:
                loop.call_soon_threadsafe(put, t)
            except RuntimeError:  # the loop has closed; the generator goes with it
                pass

        def closed() -> None:
            deliver(None)

        remove = self.gimbal._subscribe(deliver)
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
        await _in_executor(self.gimbal.close)

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
            def close_it(f: "asyncio.Future[Gimbal]") -> None:
                if f.exception() is None:
                    f.result().close()

            future.add_done_callback(close_it)
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


def connect(
    spec: str,
    *,
    protocol: Union[None, int, str] = None,
    connect_timeout_ms: int = 2000,
    raise_on_failure: bool = False,
    **config: int,
) -> _Connecting:
    """xfgcu.connect() on the asyncio loop: ``await connect(spec)`` or ``async with connect(spec)
    as gimbal``."""
    settings: Dict[str, Any] = dict(config)
    settings.update(protocol=protocol, connect_timeout_ms=connect_timeout_ms, raise_on_failure=raise_on_failure)
    return _Connecting(spec, settings)
