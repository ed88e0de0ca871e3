"""xfgcu: the XF gimbal control protocol from Python, over the project's C library (ctypes).

- codec: decode(), encode(), encode_command(), Parser: the objects and the commands of the
  xfgcu program (`decode --json`, `encode --json`, `encode COMMAND`);
- client: connect() -> Gimbal (send, set_rates, set_angles, telemetry, ...), and xfgcu.aio for
  asyncio;
- Simulator: a simulated GCU in this process, to test without hardware.
"""

from ._native import lib as _lib
from .client import CONFIG_KEYS, Gimbal, Result, connect
from .codec import Parser, commands, decode, encode, encode_command
from .errors import (
    CommandError,
    CRCError,
    DecodeError,
    EncodeError,
    Error,
    HeaderError,
    LengthError,
    LinkError,
    TruncatedError,
    UnsupportedCommandError,
)
from .sim import Simulator, model_code

__version__: str = _lib.xfpy_version().decode()

__all__ = [
    "decode",
    "encode",
    "encode_command",
    "commands",
    "Parser",
    "connect",
    "Gimbal",
    "Result",
    "CONFIG_KEYS",
    "Simulator",
    "model_code",
    "Error",
    "DecodeError",
    "HeaderError",
    "LengthError",
    "CRCError",
    "TruncatedError",
    "EncodeError",
    "CommandError",
    "UnsupportedCommandError",
    "LinkError",
]
