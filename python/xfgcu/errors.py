"""The package's exceptions and warnings.

Arguments are checked before anything reaches the library: a value of the wrong type is a
``TypeError``, a value out of range (of the C type or of the protocol), NaN, an infinity or a
string with a NUL character a ``ValueError`` (``CommandError`` for a command's arguments), each
naming the function and the parameter; nothing is sent and nothing changes.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:  # pragma: no cover
    from .results import Result

__all__ = [
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


class Error(Exception):
    """Base of every error of this package."""


class DecodeError(Error, ValueError):
    """The bytes are not one valid packet; a subclass says which fault."""


class HeaderError(DecodeError):
    """The two header bytes are neither A8 E5 (host) nor 8A 5E (GCU)."""


class LengthError(DecodeError):
    """The length field is outside 72..255, or disagrees with the bytes given."""


class CRCError(DecodeError):
    """The CRC does not match the packet's bytes."""


class TruncatedError(DecodeError):
    """Fewer bytes than a packet has, or than the length field says."""


class EncodeError(Error, ValueError):
    """An object (encode) or a command's arguments (encode_command, send) that make no packet."""


class CommandError(EncodeError):
    """A command that cannot be sent: an argument out of range, arguments that do not go
    together, a full queue."""


class UnsupportedCommandError(CommandError):
    """The GCU's model does not support the order (by V2.0.6's list); ``send(..., force=True)``
    sends it all the same."""


class CommandFailed(Error):
    """A command that did not end "ok" (the GCU failed it, or it timed out, lost its link or was
    cancelled), raised by ``send(..., check=True)`` or on a gimbal connected with
    ``raise_on_failure=True``. ``result`` is its Result."""

    def __init__(self, result: "Result") -> None:
        detail = f" (cameras 0x{result.failed_cameras:02X})" if result.failed_cameras else ""
        super().__init__(f"{result.name}: {result.status}{detail}")
        self.result = result


class LinkError(Error, ConnectionError):
    """The link cannot be opened, or the GCU did not answer in time."""


class ClosedError(LinkError):
    """A call on a Gimbal or a Simulator after its close(): every call but close() raises it."""


class TelemetryTimeout(LinkError, TimeoutError):
    """No telemetry came within the timeout a telemetry stream was given."""


class ClampedWarning(UserWarning):
    """A setpoint the library sends clamped, where it documents that it clamps: a rate beyond
    what the wire carries at the main camera's zoom (set_rates)."""
