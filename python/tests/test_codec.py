"""The codec against the xfgcu program: the same bytes, the same objects, the same errors."""

from __future__ import annotations

import warnings
from typing import Any, Dict, List, Tuple

import pytest
from hypothesis import given
from hypothesis import strategies as st

import xfgcu
from conftest import program_decode, program_encode, run

# (command, keyword arguments): one of each kind of option.
COMMANDS: List[Tuple[str, Dict[str, Any]]] = [
    ("null", {}),
    ("shutter", {}),
    ("shutter", {"cameras": "1,2"}),
    ("zoom-to", {"rate": 5.5}),
    ("zoom_to", {"fraction": 300, "cameras": 2}),
    ("zoom_in", {"cameras": "3"}),
    ("zoom_in", {"cameras": "0x03"}),
    ("gaze-geo", {"lat": 22.5, "lon": 113.9, "alt": 30}),
    ("track", {"start": True, "box": (10, 20, 110, 220)}),
    ("track", {"stop": True}),
    ("click-to-aim", {"at": (100, 9000)}),
    ("night-vision", {"mode": "auto"}),
    ("osd", {"show": True}),
    ("osd", {"hide": True}),
    ("lighting", {"level": 7}),
    ("palette", {"mode": 3}),
    ("ranging", {"on": True}),
    ("calibration", {}),
]


def cli_args(name: str, args: Dict[str, Any]) -> List[str]:
    out = [name]
    for key, value in args.items():
        out.append("--" + key.replace("_", "-"))
        if value is not True:
            out.append(",".join(map(str, value)) if isinstance(value, tuple) else str(value))
    return out


@pytest.mark.parametrize("protocol", [1, 2])
@pytest.mark.parametrize("name,args", COMMANDS)
def test_encode_command_matches_program(program: str, name: str, args: Dict[str, Any], protocol: int) -> None:
    expected = program_encode(program, "--protocol", str(protocol), *cli_args(name, args))
    assert xfgcu.encode_command(name, protocol=protocol, **args) == expected


def test_every_command_name_is_the_programs(program: str) -> None:
    names = xfgcu.commands()
    assert "zoom-to" in names and "shutter" in names and len(names) > 30
    r = run(program, "encode", "--help")
    for name in names:
        assert f"\n  {name} " in r.stdout


def test_decode_matches_program(program: str, udp_sim: xfgcu.Simulator) -> None:
    packets = [xfgcu.encode_command(n, **a) for n, a in COMMANDS]
    # GCU packets as the simulator sends them
    with xfgcu.connect(udp_sim.spec) as g:
        g.send("zoom-to", rate=3.0)
        t = g.telemetry()
    assert t is not None
    packets.append(xfgcu.encode(t.as_dict()))  # the times are ignored
    expected = program_decode(program, packets)
    for packet, obj in zip(packets, expected):
        got = xfgcu.decode(packet)
        assert list(got) == list(obj)  # the same keys, in the same order
        assert got == obj


def test_encode_is_the_inverse_of_decode() -> None:
    for name, args in COMMANDS:
        packet = xfgcu.encode_command(name, **args)
        assert xfgcu.encode(xfgcu.decode(packet)) == packet


def test_encode_accepts_what_the_program_accepts(program: str) -> None:
    obj = {"direction": "gcu", "version": 2, "order": "shutter", "feedback": {"result": "failed", "failed_cameras": 2}}
    import json

    assert xfgcu.encode(obj) == program_encode(program, "--json", json.dumps(obj))


@pytest.mark.parametrize(
    "obj,message",
    [
        ({"order": 300}, "order must be an integer 0..255"),
        ({"direction": "sideways"}, "direction"),
        ({"no_such_field": 1}, "no_such_field"),
        ({"order": "zoom_to", "command": {"zoom": 5000000}}, "zoom"),
    ],
)
def test_encode_errors_are_the_programs(program: str, obj: Dict[str, Any], message: str) -> None:
    import json

    with pytest.raises(xfgcu.EncodeError) as info:
        xfgcu.encode(obj)
    r = run(program, "encode", "--json", json.dumps(obj))
    assert r.returncode == 2
    assert message in str(info.value)
    assert str(info.value).split(": ", 1)[1] in r.stderr  # the program's message, after its "where"


@pytest.mark.parametrize(
    "name,args,error,message",
    [
        ("lighting", {"level": 300}, xfgcu.CommandError, "lighting: level=300 is out of range 0..255"),
        ("zoom-to", {}, xfgcu.CommandError, "zoom_to: give factor=X or fraction=N"),
        ("zoom_to", {"factor": 5.0, "fraction": 10}, xfgcu.CommandError, "zoom_to: factor and fraction exclude each other"),
        ("track", {"stop": True, "box": (1, 2, 3, 4)}, xfgcu.CommandError, "track: box goes only with start=True"),
        ("shutter", {"bogus": 1}, TypeError, "shutter: unexpected argument 'bogus' (it takes: cameras)"),
        ("no-such-command", {}, xfgcu.CommandError, "encode_command: 'no-such-command' is not a command"),
    ],
)
def test_encode_command_errors(name: str, args: Dict[str, Any], error: type, message: str) -> None:
    """Worded for Python: the argument as a keyword, no option spelling, no program hint."""
    with pytest.raises(error) as info:
        xfgcu.encode_command(name, **args)
    assert str(info.value).startswith(message)
    assert "--" not in str(info.value) and "xfgcu encode" not in str(info.value)


def test_encode_command_notes_are_warnings() -> None:
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        xfgcu.encode_command("fpv")  # a V0.2 order in a V0.1 packet: a note, not an error
    assert any("protocol 2" in str(w.message) for w in caught)


def test_decode_faults() -> None:
    good = xfgcu.encode_command("shutter")
    with pytest.raises(xfgcu.HeaderError):
        xfgcu.decode(b"\x00\x01" + good[2:])
    with pytest.raises(xfgcu.TruncatedError):
        xfgcu.decode(good[:40])
    with pytest.raises(xfgcu.TruncatedError):
        xfgcu.decode(good[:2])
    with pytest.raises(xfgcu.LengthError):
        xfgcu.decode(good[:2] + b"\x10\x00" + good[4:])
    with pytest.raises(xfgcu.CRCError):
        xfgcu.decode(good[:-1] + bytes([good[-1] ^ 1]))
    for cls in (xfgcu.HeaderError, xfgcu.LengthError, xfgcu.CRCError, xfgcu.TruncatedError):
        assert issubclass(cls, xfgcu.DecodeError) and issubclass(cls, ValueError)


# ---- properties ----------------------------------------------------------------------------

i16 = st.integers(-32768, 32767)
u16 = st.integers(0, 65535)
i32 = st.integers(-(2**31), 2**31 - 1)


@st.composite
def gcu_objects(draw: Any) -> Dict[str, Any]:
    return {
        "direction": "gcu",
        "version": draw(st.sampled_from([1, 2])),
        "order": draw(st.integers(0, 255)),
        "params": draw(st.binary(max_size=4)).hex().upper(),
        "cam_roll": draw(i16),
        "cam_pitch": draw(i16),
        "cam_yaw": draw(u16),
        "rate_x": draw(i16),
        "zoom_cam1": draw(u16),
        "target_distance": draw(i32),
        "target_latitude": draw(i32),
        "gimbal_code": draw(st.integers(0, 255)),
    }


@st.composite
def host_objects(draw: Any) -> Dict[str, Any]:
    return {
        "direction": "host",
        "version": draw(st.sampled_from([1, 2])),
        "order": draw(st.integers(0, 255)),
        "params": draw(st.binary(max_size=8)).hex().upper(),
        "roll_ctrl": draw(i16),
        "yaw_ctrl": draw(i16),
        "carrier_yaw": draw(u16),
        "vel_up": draw(i16),
        "latitude": draw(i32),
        "satellites": draw(st.integers(0, 255)),
        "gnss_ms": draw(st.integers(0, 2**32 - 1)),
    }


@given(st.one_of(gcu_objects(), host_objects()))
def test_roundtrip_object_packet_object(obj: Dict[str, Any]) -> None:
    packet = xfgcu.encode(obj, raw=True)  # the objects hold wire integers
    decoded = xfgcu.decode(packet, raw=True)
    for key, value in obj.items():
        assert decoded[key] == value
    assert xfgcu.encode(decoded, raw=True) == packet
    assert xfgcu.encode(xfgcu.decode(packet)) == packet  # and the engineering units


@given(st.binary(min_size=72, max_size=90))
def test_decode_never_crashes(data: bytes) -> None:
    try:
        obj = xfgcu.decode(data)
    except xfgcu.DecodeError:
        return
    assert xfgcu.encode(obj) == data


@given(
    st.lists(st.one_of(gcu_objects(), host_objects()), min_size=1, max_size=6),
    st.lists(st.binary(max_size=20), min_size=6, max_size=6),
    st.lists(st.integers(1, 200), min_size=1, max_size=30),
)
def test_parser_any_chunking(objs: List[Dict[str, Any]], noise: List[bytes], cuts: List[int]) -> None:
    packets = [xfgcu.encode(o, raw=True) for o in objs]
    # noise without header bytes, so that it cannot start a false packet
    clean = [bytes(b for b in n if b not in (0xA8, 0x8A)) for n in noise]
    stream = b"".join(c + p for c, p in zip(clean, packets))
    parser, got, at = xfgcu.Parser(), [], 0
    for cut in cuts:
        got += parser.feed(stream[at : at + cut])
        at += cut
    got += parser.feed(stream[at:])
    assert got == [xfgcu.decode(p) for p in packets]


def test_parser_direction_filter() -> None:
    host = xfgcu.encode_command("shutter")
    gcu = xfgcu.encode({"direction": "gcu", "order": "shutter"})
    assert [d["direction"] for d in xfgcu.Parser().feed(host + gcu + host)] == ["host", "gcu", "host"]
    assert [d["direction"] for d in xfgcu.Parser("gcu").feed(host + gcu + host)] == ["gcu"]
    assert xfgcu.Parser("host").feed_packets(host + gcu) == [host]


def test_cameras_int_is_a_mask_string_is_the_programs() -> None:
    # an int is a mask; a string is the program's syntax, where a decimal number is a camera
    assert xfgcu.encode_command("zoom-in", cameras=3) == xfgcu.encode_command("zoom-in", cameras="1,2")
    assert xfgcu.encode_command("zoom-in", cameras="3") == xfgcu.encode_command("zoom-in", cameras=0x04)
    with pytest.raises(xfgcu.EncodeError, match="^zoom_in: cameras=3,: expected camera numbers"):
        xfgcu.encode_command("zoom-in", cameras="3,")
