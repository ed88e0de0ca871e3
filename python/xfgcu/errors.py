"""The package's exceptions."""

from __future__ import annotations

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
    "LinkError",
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
    """An object (encode) or a command's arguments (encode_command, send) that make no packet;
    the message is the xfgcu program's."""


class CommandError(EncodeError):
    """A command that cannot be sent (bad arguments, a full queue)."""


class UnsupportedCommandError(CommandError):
    """The GCU's model does not support the order (by V2.0.6's list); ``send(..., force=True)``
    sends it all the same."""


class LinkError(Error, ConnectionError):
    """The link cannot be opened, or the GCU did not answer in time."""
