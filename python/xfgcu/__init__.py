"""xfgcu: the XF gimbal control protocol from Python, over the project's C library (ctypes).

- codec: decode(), encode(), encode_command(), Parser: the objects and the commands of the
  xfgcu program (`decode --json`, `encode --json`, `encode COMMAND`);
- client: connect() -> Gimbal (send, set_rates, set_angles, telemetry, telemetry_stream, ...),
  and xfgcu.aio for asyncio; results as Result, Telemetry, Health, statuses as str enums;
- Simulator: a simulated GCU in this process, to test without hardware.

Every argument is checked before it reaches the library: TypeError or ValueError naming the
function and the parameter, and nothing sent.
"""

from ._native import lib as _lib
from .client import CONFIG_KEYS, Gimbal, connect
from .codec import Parser, commands, decode, encode, encode_command
from .errors import (
    ClampedWarning,
    ClosedError,
    CommandError,
    CommandFailed,
    CRCError,
    DecodeError,
    EncodeError,
    Error,
    HeaderError,
    LengthError,
    LinkError,
    TelemetryTimeout,
    TruncatedError,
    UnsupportedCommandError,
)
from .results import ControlStatus, Health, LinkState, Result, Status, Telemetry
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
    "Status",
    "ControlStatus",
    "LinkState",
    "Telemetry",
    "Health",
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
    "CommandFailed",
    "LinkError",
    "ClosedError",
    "TelemetryTimeout",
    "ClampedWarning",
]
