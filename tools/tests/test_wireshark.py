"""The Wireshark dissector (tools/wireshark/xfgcu.lua) against the program, and pcap captures.

Run by ctest with Debian's Python and pytest:
    XFGCU_PROGRAM=BUILD/tools/xfgcu XFGCU_LUA=tools/wireshark/xfgcu.lua \
        /usr/bin/python3 -m pytest -q -p no:cacheprovider tools/tests/test_wireshark.py

- One voice (issue 28): on captures of every link kind (`xfgcu capture --pcap` against `xfgcu sim`
  pointed at pitch -30, yaw 45: UDP, TCP and serial, protocol V0.1 and V0.2) and on made-up packets
  (every field set, commands with scaled parameters, both directions and versions), every field
  tshark shows equals `xfgcu decode --json` (engineering units, `xfgcu.<name>`) and `decode --json
  --raw` (the raw subtree, `xfgcu.raw.<name>`), both ways: nothing missing on either side. Each
  field's label is "name (type) unit" and its description the one line of meaning, as the field
  tables of docs/protocol.md give them (generated from the same field table by another
  generator), and each engineering value is the wire integer times the step those tables state.
- Bits: the named bits of the status words (xfgcu.<word>.<bit>) with the masks the docs give,
  pod_status's read in the order decode decides (pod_status_order, pod_flags).
- Filters (an order by name, a bit, a raw field, an engineering value), frame.protocols (one xfgcu
  layer per frame), the Info column, null packets (no params item, said in words).
- TCP reassembly, expert info on a bad CRC, a bad length and a packet cut short, false headers,
  Ethernet and pcapng captures, serial (LINKTYPE_USER0) reassembly.
- The capture files themselves: replay's rejections of malformed captures, the start time of a
  text capture, decode of timestamped logs.
"""
import functools
import json
import math
import os
import re
import shutil
import struct
import subprocess
import xml.etree.ElementTree as ET

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
XFGCU = os.environ.get("XFGCU_PROGRAM", "xfgcu")
LUA = os.environ.get("XFGCU_LUA", os.path.join(HERE, "..", "wireshark", "xfgcu.lua"))
DOCS = os.path.join(HERE, "..", "..", "docs", "protocol.md")

# decode --json keys that are no field of a tree, or that compare() reads in its own way
TIMES = {"t", "time"}
# dissector fields that decode --json has no key for
TSHARK_ONLY = {"xfgcu.crc", "xfgcu.feedback.state", "xfgcu.command", "xfgcu.feedback", "xfgcu.raw",
               "xfgcu.raw.command"}
ARROW = {"host": "host→GCU", "gcu": "GCU→host"}


def run(*args, stdin=None, check=True):
    r = subprocess.run([XFGCU, *args], input=stdin, capture_output=True, text=True, timeout=60)
    if check and r.returncode != 0:
        raise AssertionError("xfgcu %s: exit %d: %s" % (" ".join(args), r.returncode, r.stderr))
    return r


def tshark(pcap, *args, home=None):
    env = dict(os.environ, HOME=home) if home else None
    cmd = ["tshark"] + (["-X", "lua_script:" + LUA, "-r", pcap] if pcap else []) + list(args)
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=120, env=env)
    # a Lua error inside the dissector shows in the packet tree (-G fields lists the field that says it)
    lua_error = "Lua: Error" in r.stderr or (pcap is not None and "Lua Error" in r.stdout)
    if r.returncode != 0 or lua_error:
        raise AssertionError("tshark %s: exit %d: %s%s" % (" ".join(args), r.returncode, r.stderr, r.stdout[-3000:]))
    return r.stdout


def packet_lines(text):
    """The packets of decode's or replay's JSON Lines; a stream's ends with its summary, checked here."""
    lines = [json.loads(line) for line in text.splitlines()]
    if lines and "summary" in lines[-1]:
        assert "direction" not in lines[-1], lines[-1]
        lines.pop()
    return lines


def decoded(source, raw=False):
    """decode --json of a pcap (a path) or of one packet (bytes), as a list of objects."""
    args = ["decode", "--json"] + (["--raw"] if raw else [])
    args += [source.hex()] if isinstance(source, bytes) else ["--file", source]
    return packet_lines(run(*args).stdout)


class Tree:
    """One xfgcu tree of a frame: its fields by name (with their show and showname), the texts."""

    def __init__(self, frame, proto):
        self.frame = frame
        self.fields = {}
        self.texts = []
        for f in proto.iter("field"):
            name = f.get("name")
            if name == "_ws.lua.text":
                self.texts.append(f.get("showname"))
            elif name.startswith("xfgcu."):
                self.fields.setdefault(name, []).append((f.get("show"), f.get("showname")))

    def show(self, name):
        values = self.fields.get(name)
        assert values and len(values) == 1, "%s: %s in frame %d" % (name, values, self.frame)
        return values[0][0]

    def showname(self, name):
        self.show(name)
        return self.fields[name][0][1]


def dissect(pcap):
    """Every xfgcu tree of a pcap, in order, and the raw PDML text."""
    text = tshark(pcap, "-T", "pdml")
    trees = []
    for frame, packet in enumerate(ET.fromstring(text).iter("packet"), start=1):
        trees += [Tree(frame, p) for p in packet.iter("proto") if p.get("name") == "xfgcu"]
    return trees, text


def columns(pcap, display_filter=None):
    """frame number -> (frame.protocols, Info) of the frames that pass the filter."""
    args = ["-T", "fields", "-E", "separator=/t", "-e", "frame.number", "-e", "frame.protocols", "-e", "_ws.col.Info"]
    out = tshark(pcap, *args, *(["-Y", display_filter] if display_filter else []))
    rows = [line.split("\t") for line in out.splitlines()]
    return {int(r[0]): (r[1], r[2]) for r in rows}


def number(text):
    return int(text, 0) if re.fullmatch(r"-?(0x[0-9a-fA-F]+|\d+)", text) else float(text)


# ---- the field tables of docs/protocol.md ------------------------------------------------------

PRETTY = {"°": "deg", "°/s": "deg/s", "m/s²": "m/s^2", "°C": "degC", "×": "x"}
NO_UNIT = {"—", "byte", "bits", "code", "by context (wire integer)"}


def unit_cell(cell):
    """A unit column ("0.01°", "1e−7°", "0.1", "ms", "0.01°/s (V0.1), 0.1°/s (V0.2)") as
    (unit, step in V0.1, step in V0.2); "" and 1 for the fields that have no unit."""
    if cell in NO_UNIT:
        return "", 1, 1
    both = re.fullmatch(r"(.+) \(V0\.1\), (.+) \(V0\.2\)", cell)
    if both:
        (u1, s1, _), (u2, s2, _) = unit_cell(both.group(1)), unit_cell(both.group(2))
        assert u1 == u2, cell
        return u1, s1, s2
    m = re.fullmatch(r"(1e−\d+|\d+(?:\.\d+)?)?\s*(.*)", cell)
    step = float(m.group(1).replace("−", "-")) if m.group(1) else 1
    return PRETTY.get(m.group(2), m.group(2)), step, step


def wire_type(cell):
    """"s16" -> "int16", "u8 ×6" (a reserved block) -> "bytes"."""
    if "×" in cell:
        return "bytes"
    return ("uint" if cell[0] == "u" else "int") + cell[1:]


def docs_tables():
    """The generated field tables: {"host": {name: row}, "gcu": ..., "params": ..., "bits": {word: {bit: row}}}."""
    with open(DOCS, encoding="utf-8") as f:
        text = f.read()
    out = {"host": {}, "gcu": {}, "params": {}, "bits": {}}
    for table, body in re.findall(r"<!-- fields: (\S+) .*?-->\n(.*?)<!-- end of fields: \1 -->", text, re.S):
        for line in body.splitlines()[2:]:
            cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
            name = cells[2 if table.startswith(("host", "gcu", "bits")) else 0].strip("`").split("[")[0]
            if table.startswith("bits-"):
                if name != "—":
                    mask = int(re.search(r"\((0x[0-9A-F]+)\)", cells[1]).group(1), 16)
                    out["bits"].setdefault(table[5:], {})[name] = {"mask": mask, "meaning": cells[3]}
                continue
            if table == "params":
                type_cell, unit, meaning = cells[2], cells[3], cells[4]
            else:
                type_cell, unit, meaning = cells[3], cells[4], cells[6]
            u, s1, s2 = unit_cell(unit)
            row = {"type": wire_type(type_cell), "unit": u, "step": (s1, s2), "meaning": meaning}
            out["host" if table.startswith("host") else "gcu" if table.startswith("gcu") else "params"][name] = row
    assert len(out["host"]) > 20 and len(out["gcu"]) > 25 and len(out["params"]) > 10 and len(out["bits"]) == 5
    return out


DOC = docs_tables()


def label(name, row, with_unit=True):
    """The label of a field as docs/protocol.md describes it: "cam_pitch (int16) deg"."""
    unit = row["unit"] if with_unit and row["type"] != "bytes" else ""
    return "%s (%s)%s" % (name, row["type"], " " + unit if unit else "")


def decimals(step):
    return max(0, -int(round(math.log10(step))))


# ---- one voice: a packet of decode --json and its tree ------------------------------------------


def same_value(got, want, what):
    assert isinstance(want, (int, float)), what
    assert number(got) == want, "%s: tshark %s, decode %r" % (what, got, want)


def check_quantity(tree, key, eng, raw, doc, version, where):
    """One field: engineering value and label under xfgcu.<key>, wire integer under xfgcu.raw.<key>,
    the step of docs/protocol.md between them."""
    name, raw_name = "xfgcu." + key, "xfgcu.raw." + key
    base = key.split(".")[-1]
    same_value(tree.show(name), eng, where + name)
    same_value(tree.show(raw_name), raw, where + raw_name)
    step = doc["step"][1 if version >= 2 else 0]
    assert abs(eng - raw * step) <= 1e-9 * max(1.0, abs(eng)), "%s%s: %r is not %r x %g" % (where, key, eng, raw, step)
    showname = tree.showname(name)
    assert showname.startswith(label(base, doc) + ": "), "%s%s: %r" % (where, name, showname)
    if step != 1:  # shown with the decimals of its step, as decode's table shows it
        assert showname == "%s: %.*f" % (label(base, doc), decimals(step), eng), showname
    assert tree.showname(raw_name).startswith(label(base, doc, with_unit=False) + ": ")


def check_bits(tree, word, value, masks, seen):
    """The named bits of a flag word read from `value`; returns the names of those set."""
    set_bits = set()
    for bit, doc in DOC["bits"][word].items():
        name = "xfgcu.%s.%s" % (word, bit)
        mask = doc["mask"]
        assert masks[name] == mask, name
        shift = (mask & -mask).bit_length() - 1
        want = (value & mask) >> shift
        assert number(tree.show(name)) == want, "%s: %s, want %d of 0x%04X" % (name, tree.show(name), want, value)
        if want:
            set_bits.add(bit)
        seen.add(name)
    return set_bits


def compare(eng, raw, tree, masks):
    """decode --json (eng) and decode --json --raw (raw) of one packet against its tree, both ways."""
    direction, version = eng["direction"], eng["version"]
    where = "frame %d %s V%d: " % (tree.frame, direction, version)
    seen = set()

    def field(key):
        seen.add("xfgcu." + key)
        return tree.show("xfgcu." + key)

    assert field("direction") == direction
    for key in ("version", "length", "order"):
        same_value(field(key), eng[key], where + key)
    for key in ("order_name", "mode_name", "gimbal_model", "pod_status_order"):
        if key in eng:
            assert field(key) == eng[key], where + key
    if eng["params"]:
        assert field("params").replace(":", "") == eng["params"].lower(), where + "params"
    else:
        assert "xfgcu.params" not in tree.fields, where + "a null packet's params"
        assert any(t.startswith(("No parameters", "No execution state")) for t in tree.texts), where + str(tree.texts)
    for key, value in eng.get("command", {}).items():
        check_quantity(tree, "command." + key, value, raw["command"][key], DOC["params"][key], version, where)
        seen |= {"xfgcu.command." + key, "xfgcu.raw.command." + key}
    if "feedback" in eng:
        assert field("feedback.result") == eng["feedback"]["result"]
        same_value(field("feedback.failed_cameras"), eng["feedback"]["failed_cameras"], where + "failed_cameras")
    docs = DOC[direction]
    for key, value in eng.items():
        if key in TIMES or key not in docs:
            continue
        if key.startswith("reserved"):
            assert field(key).replace(":", "") == value.lower(), where + key
        elif key in DOC["bits"]:
            same_value(field(key), value, where + key)
            same_value(tree.show("xfgcu.raw." + key), raw[key], where + "raw " + key)
            seen.add("xfgcu.raw." + key)
            bits = check_bits(tree, key, value if key != "pod_status" else pod_word(value, eng), masks, seen)
            if key == "pod_status":
                assert bits == set(eng["pod_flags"]), where + "pod_flags"
        else:
            check_quantity(tree, key, value, raw[key], docs[key], version, where)
            seen |= {"xfgcu." + key, "xfgcu.raw." + key}
    extra = set(tree.fields) - seen - TSHARK_ONLY
    if "command_error" in eng:  # the dissector shows the parameters even out of range
        extra = {k for k in extra if not k.startswith(("xfgcu.command.", "xfgcu.raw.command."))}
    assert extra == set(), where + "dissector fields that decode --json lacks"
    return len(seen)


def pod_word(word, eng):
    """pod_status as its flags are read: its two bytes swapped when decode read it big-endian."""
    return ((word >> 8) | ((word & 0xFF) << 8)) if eng["pod_status_order"] == "be" else word


# ---- fixtures -----------------------------------------------------------------------------------


@pytest.fixture(scope="session")
def tmp(tmp_path_factory):
    return str(tmp_path_factory.mktemp("ws"))


@pytest.fixture(scope="session")
def fields(tmp):
    """tshark -G fields with the dissector in a plugin folder (-X lua_script is not read for -G):
    abbreviation -> [(label, type, base, mask, description)]."""
    home = os.path.join(tmp, "home")
    plugins = os.path.join(home, ".local", "lib", "wireshark", "plugins")
    os.makedirs(plugins, exist_ok=True)
    shutil.copy(LUA, plugins)
    out = {}
    for line in tshark(None, "-G", "fields", home=home).splitlines():
        cols = line.split("\t")
        if cols[0] == "F" and cols[2].startswith("xfgcu."):
            out.setdefault(cols[2], []).append((cols[1], cols[3], cols[5], int(cols[6], 16), cols[7]))
    assert out, "no xfgcu field: the dissector did not load from %s" % plugins
    return out


@pytest.fixture(scope="session")
def masks(fields):
    return {abbr: rows[0][3] for abbr, rows in fields.items()}


class Sim:
    """`xfgcu sim` on a free port or a pty, stopped at the end."""

    def __init__(self, link, *extra):
        self.proc = subprocess.Popen([XFGCU, "sim", "--" + link] + (["0"] if link != "pty" else []) +
                                     ["--duration", "60", *extra], stdout=subprocess.PIPE, text=True)
        line = self.proc.stdout.readline().strip()  # "xfgcu sim: listening on udp 127.0.0.1:PORT"
        where = line.rsplit(" ", 1)[-1]
        if link == "udp":
            self.args = ["--link", "udp:127.0.0.1:%s,local=0" % where.rsplit(":", 1)[1]]
        elif link == "tcp":
            self.args = ["--link", "tcp:" + where]
        else:
            self.args = ["--link", "serial:" + where]

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.proc.terminate()
        self.proc.wait(timeout=10)
        self.proc.stdout.close()


LINKS = [("udp", 1), ("tcp", 2), ("pty", 1), ("pty", 2)]


@pytest.fixture(scope="session")
def captures(tmp):
    """(link, version) -> a pcap of `xfgcu capture --pcap ... shutter` against a simulator that was
    pointed at pitch -30, yaw 45 first."""
    out = {}
    for link, version in LINKS:
        pcap = os.path.join(tmp, "%s-v%d.pcap" % (link, version))
        with Sim(link, "--protocol", str(version)) as sim:
            proto = ["--protocol", str(version)]
            run(*sim.args, *proto, "point", "--pitch", "-30", "--yaw", "45")
            run(*sim.args, *proto, "capture", "--pcap", pcap, "--count", "6", "shutter")
        out[(link, version)] = pcap
    return out


def ip_packet(proto, src, dst, sport, dport, payload, seq=0, ack=0):
    if proto == 6:
        l4 = struct.pack(">HHIIBBHHH", sport, dport, seq, ack, 0x50, 0x18, 65535, 0, 0)
    else:
        l4 = struct.pack(">HHHH", sport, dport, 8 + len(payload), 0)
    total = 20 + len(l4) + len(payload)
    ip = struct.pack(">BBHHHBBH4s4s", 0x45, 0, total, 1, 0x4000, 64, proto, 0, bytes(src), bytes(dst))
    return ip + l4 + payload


def write_pcap(path, linktype, records):
    with open(path, "wb") as f:
        f.write(struct.pack("<IHHiIII", 0xA1B2C3D4, 2, 4, 0, 0, 65535, linktype))
        for i, data in enumerate(records):
            f.write(struct.pack("<IIII", 1000 + i, 0, len(data), len(data)) + data)


HOST, GCU = [10, 0, 0, 1], [10, 0, 0, 2]


def udp_pcap(path, packets):
    """Each packet in a datagram to or from the GCU's port 2337 (by its header's direction)."""
    records = [ip_packet(17, HOST, GCU, 2338, 2337, p) if p[0] == 0xA8 else ip_packet(17, GCU, HOST, 2337, 2338, p)
               for p in packets]
    write_pcap(path, 101, records)
    return path


def encode(*args):
    return bytes.fromhex(run("encode", *args).stdout.strip().replace(" ", ""))


def encode_json(obj, raw=True, check=True):
    r = run("encode", "--json", *(["--raw"] if raw else []), "-", stdin=json.dumps(obj), check=check)
    return bytes.fromhex(r.stdout.strip().replace(" ", "")) if r.returncode == 0 else None


def every_field(direction, version):
    """A packet whose every field and reserved byte holds its own value, as large as it takes."""
    base = decoded(encode_json({"direction": direction, "version": version}), raw=True)[0]
    obj = {"direction": direction, "version": version}
    names = [k for k in base if k in DOC[direction]] + ["reserved_main", "reserved_sub"]
    for i, name in enumerate(names):
        if name.startswith("reserved"):
            tries = [("%02X" % (0xA0 + i)) * n for n in range(1, 9)]
        else:
            big, mid = 0x01020304 * (i + 1) % 0x7FFFFFFF, 0x0102 + 0x0101 * i
            # negative where the field is signed, else the top bit set: a wrong sign shows
            tries = [-big, -mid, -(i + 2), 0x80000000 + i, 0x8000 + i, 0x80 + i]
        for value in tries:
            if encode_json(dict(obj, **{name: value}), check=False) is not None:
                obj[name] = value
                break
        else:
            pytest.fail("no value of %s encodes" % name)
    return encode_json(obj)


@pytest.fixture(scope="session")
def made_up(tmp):
    """A UDP pcap of made-up packets: every field set, in both directions and versions; commands
    with scaled parameters; pod status words read either way."""
    packets = [every_field(d, v) for d in ("host", "gcu") for v in (1, 2)]
    packets += [encode("--protocol", "2", "temp-alarm", "--on", "--high", "45.5", "--low", "-10.5"),
                encode("gaze-geo", "--lat", "38.0300822", "--lon", "-117.1234567", "--alt", "41.123"),
                encode("--protocol", "2", "time-zone", "--hours", "-5"),
                encode("zoom-to", "--factor", "5.5"),
                encode("track", "--start", "--box", "1,2,3000,4000")]
    for word, version in ((0x8001, 1), (0x1001, 2), (0x0001, 1)):  # V2.0.6's 01 80; 01 10; undecided
        packets.append(encode_json({"direction": "gcu", "version": version, "pod_status": word, "order": "shutter",
                                    "feedback": {"result": "ok"}}))
    return udp_pcap(os.path.join(tmp, "made-up.pcap"), packets), packets


@functools.lru_cache(maxsize=None)
def all_packets(pcap):
    eng, raw = decoded(pcap), decoded(pcap, raw=True)
    trees, pdml = dissect(pcap)
    assert len(eng) == len(raw) == len(trees) > 0, "decode %d, tshark %d packets" % (len(eng), len(trees))
    return eng, raw, trees, pdml


# ---- the tests ----------------------------------------------------------------------------------


def test_labels_and_descriptions(fields):
    """Every field of the field tables has its Wireshark fields, labelled "name (type) unit" with
    the docs' one line of meaning, its wire integer under xfgcu.raw.<name>, and its named bits; and
    no xfgcu.<name> field is without a row."""
    def has(abbr, text, blurb, ftype=None):
        rows = fields.get(abbr, [])
        # Wireshark drops a description that repeats the label (the bit "recording")
        assert any(r[0] == text and r[4] == ("" if blurb == text else blurb) and (ftype is None or r[1] == ftype)
                   for r in rows), \
            "%s: want %r / %r, have %s" % (abbr, text, blurb, rows)

    for direction in ("host", "gcu"):
        for name, row in DOC[direction].items():
            blurb = row["meaning"]
            host, gcu = DOC["host"].get(name), DOC["gcu"].get(name)
            if host and gcu and host["meaning"] != gcu["meaning"]:  # one field per name: both meanings
                blurb = "host: %s; GCU: %s" % (host["meaning"], gcu["meaning"])
            has("xfgcu." + name, label(name, row), blurb, "FT_DOUBLE" if row["step"] != (1, 1) else None)
            if row["type"] != "bytes":
                has("xfgcu.raw." + name, label(name, row, with_unit=False), blurb)
    for name, row in DOC["params"].items():
        has("xfgcu.command." + name, label(name, row), row["meaning"])
        has("xfgcu.raw.command." + name, label(name, row, with_unit=False), row["meaning"])
    for word, bits in DOC["bits"].items():
        for bit, row in bits.items():
            single = row["mask"] & (row["mask"] - 1) == 0
            has("xfgcu.%s.%s" % (word, bit), bit, row["meaning"], "FT_BOOLEAN" if single else None)
            assert fields["xfgcu.%s.%s" % (word, bit)][0][3] == row["mask"]
    known = set(DOC["host"]) | set(DOC["gcu"])
    for abbr in fields:
        parts = abbr.split(".")
        if parts[1] == "raw" and len(parts) > 2:
            assert parts[-1] in (known if len(parts) == 3 else DOC["params"]) or abbr == "xfgcu.raw.command", abbr
        elif parts[1] == "command" and len(parts) == 3:
            assert parts[2] in DOC["params"], abbr
        elif len(parts) == 3 and parts[1] in DOC["bits"]:
            assert parts[2] in DOC["bits"][parts[1]], abbr
    same = {"xfgcu.%s.%s" % (w, b) for w, bits in DOC["bits"].items() for b, row in bits.items() if b == row["meaning"]}
    same |= {"xfgcu.bad_crc", "xfgcu.bad_length", "xfgcu.noise.expert"}  # expert info: its text says it
    for abbr, rows in fields.items():
        assert all(r[4] for r in rows) or abbr in same, "%s has no description" % abbr


@pytest.mark.parametrize("link,version", LINKS)
def test_one_voice_captures(captures, masks, link, version):
    """The same packets, captured on each link in each version, read the same in decode --json,
    decode --json --raw and tshark (issue 28's Done-when, the Wireshark side)."""
    eng, raw, trees, pdml = all_packets(captures[(link, version)])
    assert "MISSING" not in pdml
    for e, r, t in zip(eng, raw, trees):
        assert compare(e, r, t, masks) >= (25 if e["direction"] == "host" else 35)
    gcu = [e for e in eng if e["direction"] == "gcu" and e["version"] == version]
    assert gcu and all(e["cam_pitch"] == -30.0 and e["cam_yaw"] == 45.0 for e in gcu)
    assert any("feedback" in e for e in eng) and any("command" in e for e in eng)
    assert any(not e["params"] for e in eng)  # null packets


def test_one_voice_made_up(made_up, masks):
    """Every field set to a value of its own, commands with scaled parameters, both versions and
    directions; pod status words read big-endian, little-endian and undecided."""
    pcap, packets = made_up
    eng, raw, trees, _ = all_packets(pcap)
    assert len(trees) == len(packets)
    for e, r, t in zip(eng, raw, trees):
        compare(e, r, t, masks)
    assert {(e["direction"], e["version"]) for e in eng} == {(d, v) for d in ("host", "gcu") for v in (1, 2)}
    assert [e["pod_status_order"] for e in eng[-3:]] == ["be", "le", "le"]
    assert eng[-3]["pod_flags"] == ["target_valid", "ranging_on"]
    scaled = {k: v for e in eng for k, v in e.get("command", {}).items()}
    assert scaled["temp_high"] == 45.5 and scaled["latitude"] == 38.0300822 and scaled["hours"] == -5


def frames_of(pcap, pred):
    """The frame numbers of the packets for which pred(decode --json, decode --json --raw) holds."""
    eng, raw, trees, _ = all_packets(pcap)
    return {t.frame for e, r, t in zip(eng, raw, trees) if pred(e, r)}


@pytest.mark.parametrize("link,version", LINKS)
def test_filters(captures, link, version):
    pcap = captures[(link, version)]
    cases = [
        ('xfgcu.order == "shutter"', lambda e, r: e.get("order_name") == "shutter"),
        ("xfgcu.raw.cam_pitch == -3000", lambda e, r: r.get("cam_pitch") == -3000),
        ("xfgcu.cam_yaw == 45", lambda e, r: e.get("cam_yaw") == 45.0),
        ('xfgcu.feedback.result == "ok"', lambda e, r: e.get("feedback", {}).get("result") == "ok"),
    ]
    if version == 2:
        cases.append(("xfgcu.camera_status.osd_on == 1", lambda e, r: e.get("camera_status", 0) & 0x2000))
    for flt, pred in cases:
        want = frames_of(pcap, pred)
        assert want, flt
        assert set(columns(pcap, flt)) == want, flt


def test_bit_filter_pod_status(made_up):
    pcap, _ = made_up
    want = frames_of(pcap, lambda e, r: "ranging_on" in e.get("pod_flags", []))
    assert want and set(columns(pcap, "xfgcu.pod_status.ranging_on == 1")) == want
    assert set(columns(pcap, 'xfgcu.pod_status_order == "be"')) == frames_of(pcap, lambda e, r: e.get("pod_status_order") == "be")


def expected_info(e):
    """The Info column of one packet of the captures (null and shutter)."""
    text = ARROW[e["direction"]] + " " + e["order_name"]
    if e["direction"] == "host":
        return text + "".join(" %s 0x%02X" % (k, v) for k, v in e.get("command", {}).items())
    if "feedback" in e:
        text += " " + e["feedback"]["result"]
    return text + " pitch %.2f° yaw %.2f°" % (e["cam_pitch"], e["cam_yaw"])


@pytest.mark.parametrize("link,version", LINKS)
def test_protocols_and_info(captures, link, version):
    """One xfgcu layer per frame, and an Info column that says each packet once: its direction,
    order, execution state and the camera's angles."""
    pcap = captures[(link, version)]
    eng, _, trees, _ = all_packets(pcap)
    want = {}
    for e, t in zip(eng, trees):
        want.setdefault(t.frame, []).append(expected_info(e))
    cols = columns(pcap)
    for frame, (protocols, info) in cols.items():
        assert protocols.split(":").count("xfgcu") == 1, (frame, protocols)
        if frame in want:
            assert info == "; ".join(want[frame]), (frame, info)
        else:  # a serial chunk that ends no packet, or a TCP segment without data
            assert link == "pty" and info.endswith("bytes, part of a packet") or link == "tcp", (frame, info)
    assert "GCU→host shutter ok pitch -30.00° yaw 45.00°" in [i for _, i in cols.values()]
    assert "host→GCU shutter cameras 0x01" in [i for _, i in cols.values()]


def test_info_control_and_failure(tmp):
    """A host packet whose control quantities are valid shows them (wire integers: their unit is
    the mode's); a failed camera order shows the cameras that failed."""
    ctrl = encode_json({"status": 5, "pitch_ctrl": -3000, "yaw_ctrl": 4500, "order": "euler"})
    failed = encode_json({"direction": "gcu", "version": 2, "order": "zoom_to", "params": "02", "cam_pitch": -1234})
    unknown = encode_json({"order": 0x99, "params": "0102"})
    pcap = udp_pcap(os.path.join(tmp, "info.pcap"), [ctrl, failed, unknown])
    assert [i for _, i in columns(pcap).values()] == ["host→GCU euler ctrl roll 0 pitch -3000 yaw 4500",
                                                      "GCU→host zoom_to failed (cameras 0x02) pitch -12.34° yaw 0.00°",
                                                      "host→GCU order 0x99"]


def test_tcp_reassembly(tmp, masks):
    a, b, c = encode("zoom-to", "--factor", "5.5"), encode("null"), encode("shutter")
    pcap = os.path.join(tmp, "reassembly.pcap")
    segs = [a[:30], a[30:] + b + c]  # one packet split over two segments, then two in one
    records, seq = [], 1
    for s in segs:
        records.append(ip_packet(6, HOST, GCU, 40000, 2332, s, seq=seq, ack=1))
        seq += len(s)
    write_pcap(pcap, 101, records)
    trees, _ = dissect(pcap)
    assert [t.frame for t in trees] == [2, 2, 2]  # the three packets end in the second frame
    for p, t in zip((a, b, c), trees):
        compare(decoded(p)[0], decoded(p, raw=True)[0], t, masks)
    assert columns(pcap)[2][1] == "host→GCU zoom_to cameras 0x01 zoom -55; host→GCU null; host→GCU shutter cameras 0x01"


def test_bad_crc_and_length(tmp):
    good = encode("shutter")
    bad_crc = good[:-1] + bytes([good[-1] ^ 0xFF])
    bad_len = good[:2] + struct.pack("<H", 300) + good[4:]
    pcap = os.path.join(tmp, "bad.pcap")
    cut, stub = good[:40], good[:3]  # a datagram holds a packet cut short: said, not waited for
    lone = good[:1]  # a datagram that ends in a lone header byte: noise, not a wait for more
    write_pcap(pcap, 101, [ip_packet(17, HOST, GCU, 2338, 2337, p) for p in (good, bad_crc, bad_len, cut, stub, lone)])
    frames = [ET.tostring(p, encoding="unicode") for p in ET.fromstring(tshark(pcap, "-T", "pdml")).iter("packet")]
    assert "xfgcu.bad_crc" not in frames[0]
    assert "xfgcu.bad_crc" in frames[1]
    assert "xfgcu.bad_length" in frames[2]
    assert "the length field says %d bytes, the datagram holds 40" % len(good) in frames[3]
    assert "Truncated: no length field" in frames[4]
    assert "xfgcu.noise" in frames[5]
    cols = columns(pcap)
    assert cols[2][1] == "host→GCU shutter cameras 0x01 [bad CRC]"
    assert all(p.split(":").count("xfgcu") == 1 for p, _ in cols.values())  # by port, not heuristics


def test_false_header_then_packet(tmp, masks):
    # noise that looks like a header with a length in range (A8 E5 48 00), then a real packet: the
    # packet is dissected whole (the library's parser finds it too), over UDP, TCP and serial
    pkt = encode("shutter")
    data = bytes([0xA8, 0xE5, 0x48, 0x00]) + pkt
    cases = [
        ("false_udp.pcap", 101, [ip_packet(17, HOST, GCU, 2338, 2337, data)]),
        ("false_tcp.pcap", 101, [ip_packet(6, HOST, GCU, 40000, 2332, data, seq=1, ack=1)]),
        ("false_serial.pcap", 147, [b">" + data]),
    ]
    for name, linktype, records in cases:
        pcap = os.path.join(tmp, name)
        write_pcap(pcap, linktype, records)
        trees, _ = dissect(pcap)
        assert len(trees) == 1, name
        compare(decoded(pkt)[0], decoded(pkt, raw=True)[0], trees[0], masks)


def test_ethernet_and_pcapng(tmp):
    """tcpdump's Ethernet captures and Wireshark's pcapng are read too."""
    pkt, reply = encode("shutter"), encode("null")
    eth = bytes(12) + b"\x08\x00"
    pcap = os.path.join(tmp, "eth.pcap")
    write_pcap(pcap, 1, [eth + ip_packet(17, HOST, GCU, 2338, 2337, p) for p in (pkt, reply)])
    ng = os.path.join(tmp, "eth.pcapng")
    subprocess.run(["editcap", "-F", "pcapng", pcap, ng], check=True, capture_output=True)
    for f in (pcap, ng):
        out = packet_lines(run("replay", f, "--json", "--raw").stdout)
        assert [o["order_name"] for o in out] == ["shutter", "null"]
        assert run("decode", "--json", "--raw", "--file", f).stdout == run("replay", f, "--json", "--raw").stdout
        assert len(dissect(f)[0]) == 2


def test_serial_user0(tmp, masks):
    pkt = encode("shutter")
    pcap = os.path.join(tmp, "serial.pcap")
    write_pcap(pcap, 147, [b">" + pkt[:5], b">" + pkt[5:] + pkt[:1], b">" + pkt[1:]])
    trees, _ = dissect(pcap)
    assert [t.frame for t in trees] == [2, 3]
    compare(decoded(pkt)[0], decoded(pkt, raw=True)[0], trees[0], masks)
    assert [i for _, i in columns(pcap).values()] == ["host→GCU 5 bytes, part of a packet",
                                                      "host→GCU shutter cameras 0x01",
                                                      "host→GCU shutter cameras 0x01"]
    assert len(packet_lines(run("replay", pcap, "--json", "--raw").stdout)) == 2


def test_replay_matches_decode(captures):
    for pcap in captures.values():
        assert decoded(pcap, raw=True) == packet_lines(run("replay", pcap, "--json", "--raw").stdout)


def test_capture_refuses_existing_file(tmp):
    pcap = os.path.join(tmp, "exists.pcap")
    with open(pcap, "w") as f:
        f.write("keep")
    r = run("--tcp", "127.0.0.1:1", "--timeout", "200", "capture", "--pcap", pcap, check=False)
    assert r.returncode == 2
    with open(pcap) as f:
        assert f.read() == "keep"


# ---- capture files ------------------------------------------------------------------------------


def write_text(tmp, name, text):
    path = os.path.join(tmp, name)
    with open(path, "wb") as f:
        f.write(text.encode("latin-1"))
    return path


def rejects(tmp, body, line, reason):
    path = write_text(tmp, "bad.cap", "# xfgcu capture 1\n" + body)
    r = run("replay", path, check=False)
    assert r.returncode == 2 and r.stdout == ""
    assert r.stderr.count("\n") == 1, r.stderr
    assert r.stderr.startswith("xfgcu: %s:%d: " % (path, line)), r.stderr
    assert reason in r.stderr


def test_replay_rejections(tmp):
    rejects(tmp, "-1.000 > A8\n", 2, "negative time")
    rejects(tmp, "0.000 > A8\n0.001 > A8 E5\x00 00\n", 3, "NUL")
    rejects(tmp, "0.000 > A8 G5\n", 2, "hex")
    rejects(tmp, "0.000 > A8 E\n", 2, "hex")
    rejects(tmp, "2.000 > A8\n1.000 < 8A\n", 3, "goes back")
    rejects(tmp, "4294968.000 > A8\n", 2, "too large")
    rejects(tmp, "1.5 > A8\n", 2, "milliseconds")
    rejects(tmp, "0.000 ! A8\n", 2, "'>' or '<'")
    rejects(tmp, "# start yesterday\n", 2, "start time")
    rejects(tmp, "0.000 > A8 ", 2, "hex")  # a line that ends in a space, no newline
    path = write_text(tmp, "bad17.cap", "# xfgcu capture 17\n")  # the first line, exactly
    r = run("replay", path, check=False)
    assert r.returncode == 2 and "not an xfgcu capture" in r.stderr
    rejects(tmp, "# start 2026-13-26T10:00:00.123Z\n", 2, "start time")  # month 13
    rejects(tmp, "# start 2026-11-26T24:00:00.123Z\n", 2, "start time")  # hour 24
    rejects(tmp, "# start 2026-11-26T10:00:00.123Z junk\n", 2, "start time")


def test_start_time(tmp):
    pkt = run("encode", "null").stdout.strip()
    path = write_text(tmp, "start.cap", "# xfgcu capture 1\n# start 2026-11-26T10:00:00.123Z\n1.500 > %s\n" % pkt)
    obj = packet_lines(run("replay", path, "--json", "--raw").stdout)[0]
    assert obj["t"] == 1.5 and obj["time"] == "2026-11-26T10:00:01.623Z"
    old = write_text(tmp, "old.cap", "# xfgcu capture 1\n0.000 > %s\n" % pkt)  # without a start: still read
    assert "time" not in packet_lines(run("replay", old, "--json", "--raw").stdout)[0]


def test_decode_logs(tmp):
    p, q = run("encode", "shutter").stdout.strip(), run("encode", "null").stdout.strip()
    half = (len(p) // 6) * 3  # on a byte boundary: "A8 E5 "
    log = ("12.345 %s\n[2026-11-26 10:00:00.123] %s\n2026-11-26T10:00:01.5Z %s\n[7.25] %s\n%s\n" %
           (p, q, p[:half], p[half:], q))
    out = packet_lines(run("decode", "--json", "--raw", stdin=log).stdout)
    assert [o.get("t", o.get("time")) for o in out] == [12.345, "2026-11-26T10:00:00.123", 7.25, 7.25]
    assert [o["order_name"] for o in out] == ["shutter", "null", "shutter", "null"]
    path = write_text(tmp, "log.txt", log)
    assert len(packet_lines(run("decode", "--json", "--raw", "--file", path).stdout)) == 4
    cap = write_text(tmp, "t.cap", "# xfgcu capture 1\n0.250 > %s\n" % p)
    with open(cap) as f:
        assert packet_lines(run("decode", "--json", "--raw", stdin=f.read()).stdout)[0]["t"] == 0.25
    r = run("decode", stdin="12.345 %s zz\n" % p, check=False)
    assert r.returncode == 2 and "line 1 column" in r.stderr
