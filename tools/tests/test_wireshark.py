"""The Wireshark dissector and pcap captures (issue 16), and the capture items of issue 15.

Run by ctest with Debian's interpreter:
    /usr/bin/python3 test_wireshark.py XFGCU_EXE tools/wireshark/xfgcu.lua

- the simulator on UDP, TCP and a pty; `xfgcu capture --pcap` of each (a command included, the
  TCP one in protocol V0.2); tshark with the dissector over each pcap; every field of every
  packet compared with `xfgcu decode --json --raw` of the same pcap (the dissector shows wire
  integers), both ways (no field missing on either side); `xfgcu replay` of the pcap gives the
  same packets;
- a made-up TCP capture on port 2332: a packet split over two segments, two packets in one;
- expert info on a bad CRC, a bad length and a packet cut short (UDP port 2337);
- replay's rejections of malformed captures (one line `xfgcu: FILE:LINE: reason`, exit 2), the
  start time of a text capture, and decode of timestamped logs.
"""
import atexit
import json
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import unittest

XFGCU = sys.argv[1] if len(sys.argv) > 1 else "xfgcu"
LUA = sys.argv[2] if len(sys.argv) > 2 else "tools/wireshark/xfgcu.lua"
TMP = tempfile.mkdtemp(prefix="xfgcu-ws-")
atexit.register(shutil.rmtree, TMP, True)

# decode --json keys that are not fields of the frames (the dissector has them otherwise or not at all)
EXTRAS = {"t", "time", "direction", "version", "length", "order", "order_name", "params", "command",
          "command_error", "feedback", "mode_name", "gimbal_model", "pod_status_order", "pod_flags", "warnings"}
# dissector fields that decode --json has no key for
TSHARK_ONLY = {"xfgcu.crc", "xfgcu.feedback.state", "xfgcu.command", "xfgcu.feedback"}


def run(*args, stdin=None, check=True):
    r = subprocess.run([XFGCU, *args], input=stdin, capture_output=True, text=True, timeout=30)
    if check and r.returncode != 0:
        raise AssertionError("xfgcu %s: exit %d: %s" % (" ".join(args), r.returncode, r.stderr))
    return r


class Sim:
    """`xfgcu sim` on a free port or a pty, stopped at the end."""

    def __init__(self, link, *extra):
        self.proc = subprocess.Popen([XFGCU, "sim", "--" + link] + (["0"] if link != "pty" else []) +
                                     ["--duration", "30", *extra], stdout=subprocess.PIPE, text=True)
        line = self.proc.stdout.readline().strip()  # "xfgcu sim: listening on udp 127.0.0.1:PORT"
        where = line.rsplit(" ", 1)[-1]
        if link == "udp":
            self.args = ["--udp", "127.0.0.1", "--gcu-port", where.rsplit(":", 1)[1], "--local-port", "0"]
        elif link == "tcp":
            self.args = ["--tcp", where]
        else:
            self.args = ["--serial", where]

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.proc.terminate()
        self.proc.wait(timeout=10)
        self.proc.stdout.close()


def pairs_hook(pairs):
    return pairs  # keep repeated keys (several xfgcu trees in one frame)


def tshark_json(pcap):
    r = subprocess.run(["tshark", "-X", "lua_script:" + LUA, "-r", pcap, "-T", "json"], capture_output=True,
                       text=True, timeout=60)
    # a Lua error inside the dissector shows in the packet tree, not on stderr
    if r.returncode != 0 or "Lua: Error" in r.stderr or "Lua Error" in r.stdout:
        raise AssertionError("tshark: %s%s" % (r.stderr, "; a Lua error in the tree" if "Lua Error" in r.stdout else ""))
    return json.loads(r.stdout, object_pairs_hook=pairs_hook)


def flatten(pairs, out):
    """The xfgcu.* fields of one xfgcu tree, subtrees included."""
    for key, value in pairs:
        if isinstance(value, list) and value and isinstance(value[0], tuple):
            flatten(value, out)
        elif key.startswith("xfgcu."):
            out[key] = value
    return out


def xfgcu_trees(frames):
    """Every xfgcu tree of every frame, in order, as {field: text}."""
    trees = []
    for frame in frames:
        source = dict(frame)["_source"]
        for key, layer in dict(source)["layers"]:
            if key == "xfgcu":
                trees.append(flatten(layer, {}))
    return trees


def experts(frames):
    return json.dumps(frames)


def colon_hex(text):
    return ":".join(text[i:i + 2] for i in range(0, len(text), 2)).lower()


def compare(test, pkt, tree):
    """decode --json's object against the dissector's fields, both ways."""
    seen = set()

    def same(key, want):
        name = "xfgcu." + key
        test.assertIn(name, tree, "%s missing in the dissector's tree of %s" % (name, pkt))
        got = tree[name]
        if isinstance(want, int):
            test.assertEqual(int(got, 0), want, name)
        else:
            test.assertEqual(got, want, name)
        seen.add(name)

    same("direction", pkt["direction"])
    same("version", pkt["version"])
    same("length", pkt["length"])
    same("order", pkt["order"])
    same("params", colon_hex(pkt["params"]))
    for key, value in pkt.items():
        if key in EXTRAS:
            continue
        same(key, colon_hex(value) if key.startswith("reserved") else value)
    for key, value in pkt.get("command", {}).items():
        same("command." + key, value)
    if "feedback" in pkt:
        same("feedback.result", pkt["feedback"]["result"])
        same("feedback.failed_cameras", pkt["feedback"]["failed_cameras"])
    extra = set(tree) - seen - TSHARK_ONLY
    if "command_error" in pkt:  # the dissector shows the parameters even out of range
        extra = {k for k in extra if not k.startswith("xfgcu.command.")}
    test.assertEqual(extra, set(), "dissector fields that decode --json lacks")


def write_pcap(path, linktype, records):
    with open(path, "wb") as f:
        f.write(struct.pack("<IHHiIII", 0xA1B2C3D4, 2, 4, 0, 0, 65535, linktype))
        for i, data in enumerate(records):
            f.write(struct.pack("<IIII", 1000 + i, 0, len(data), len(data)) + data)


def ip_packet(proto, src, dst, sport, dport, payload, seq=0, ack=0):
    if proto == 6:
        l4 = struct.pack(">HHIIBBHHH", sport, dport, seq, ack, 0x50, 0x18, 65535, 0, 0)
    else:
        l4 = struct.pack(">HHHH", sport, dport, 8 + len(payload), 0)
    total = 20 + len(l4) + len(payload)
    ip = struct.pack(">BBHHHBBH4s4s", 0x45, 0, total, 1, 0x4000, 64, proto, 0, bytes(src), bytes(dst))
    return ip + l4 + payload


def packet_lines(text):
    """The packets of decode's or replay's JSON Lines, after checking that the last line is their summary."""
    lines = [json.loads(line) for line in text.splitlines()]
    assert "summary" in lines[-1] and "direction" not in lines[-1], lines[-1]
    return lines[:-1]


def encode(*args):
    return bytes.fromhex(run("encode", *args).stdout.strip().replace(" ", ""))


class RecordedPcaps(unittest.TestCase):
    def check_link(self, link, extra_sim=(), extra_cli=()):
        pcap = os.path.join(TMP, link + ".pcap")
        with Sim(link, *extra_sim) as sim:
            run(*sim.args, *extra_cli, "capture", "--pcap", pcap, "--count", "6", "zoom-to", "--factor", "5.5")
        packets = packet_lines(run("decode", "--file", pcap, "--json", "--raw").stdout)
        trees = xfgcu_trees(tshark_json(pcap))
        self.assertGreaterEqual(len(packets), 12)
        self.assertEqual(len(trees), len(packets), "tshark and decode count different packets")
        for pkt, tree in zip(packets, trees):
            compare(self, pkt, tree)
        self.assertTrue(any("command" in p for p in packets) and any("feedback" in p for p in packets))
        replayed = packet_lines(run("replay", pcap, "--json", "--raw").stdout)
        self.assertEqual(replayed, packets)
        return packets

    def test_udp(self):
        self.check_link("udp")

    def test_tcp_v02(self):
        packets = self.check_link("tcp", ("--protocol", "2"), ("--protocol", "2"))
        self.assertTrue(all(p["version"] == 2 for p in packets))
        self.assertTrue(any("thermal_status" in p for p in packets))  # a V0.2 GCU field

    def test_pty(self):
        self.check_link("pty")

    def test_capture_refuses_existing_file(self):
        pcap = os.path.join(TMP, "exists.pcap")
        with open(pcap, "w") as f:
            f.write("keep")
        r = run("--tcp", "127.0.0.1:1", "--timeout", "200", "capture", "--pcap", pcap, check=False)
        self.assertEqual(r.returncode, 2)
        with open(pcap) as f:
            self.assertEqual(f.read(), "keep")


class MadeUpPcaps(unittest.TestCase):
    def test_tcp_reassembly(self):
        a, b, c = encode("zoom-to", "--factor", "5.5"), encode("null"), encode("shutter")
        host, gcu = [10, 0, 0, 1], [10, 0, 0, 2]
        pcap = os.path.join(TMP, "reassembly.pcap")
        segs = [a[:30], a[30:] + b + c]  # one packet split over two segments, then two in one
        records, seq = [], 1
        for s in segs:
            records.append(ip_packet(6, host, gcu, 40000, 2332, s, seq=seq, ack=1))
            seq += len(s)
        write_pcap(pcap, 101, records)
        frames = tshark_json(pcap)
        trees = xfgcu_trees(frames)
        self.assertEqual(len(trees), 3)
        hexes = [x.hex() for x in (a, b, c)]
        packets = [json.loads(run("decode", "--json", "--raw", h).stdout) for h in hexes]
        for pkt, tree in zip(packets, trees):
            compare(self, pkt, tree)
        # the three packets end in the second frame
        self.assertEqual(sum(1 for k, _ in dict(dict(frames[1])["_source"])["layers"] if k == "xfgcu"), 3)

    def test_bad_crc_and_length(self):
        good = encode("shutter")
        bad_crc = good[:-1] + bytes([good[-1] ^ 0xFF])
        bad_len = good[:2] + struct.pack("<H", 300) + good[4:]
        host, gcu = [10, 0, 0, 1], [10, 0, 0, 2]
        pcap = os.path.join(TMP, "bad.pcap")
        cut, stub = good[:40], good[:3]  # a datagram holds a packet cut short: said, not waited for
        lone = good[:1]  # a datagram that ends in a lone header byte: noise, not a wait for more
        write_pcap(pcap, 101, [ip_packet(17, host, gcu, 2338, 2337, p) for p in (good, bad_crc, bad_len, cut, stub, lone)])
        frames = tshark_json(pcap)
        self.assertNotIn("xfgcu.bad_crc", experts(frames[0]))
        self.assertIn("xfgcu.bad_crc", experts(frames[1]))
        self.assertIn("xfgcu.bad_length", experts(frames[2]))
        self.assertIn("the length field says %d bytes, the datagram holds 40" % len(good), experts(frames[3]))
        self.assertIn("Truncated: no length field", experts(frames[4]))
        self.assertIn("xfgcu.noise", experts(frames[5]))

    def test_false_header_then_packet(self):
        # noise that looks like a header with a length in range (A8 E5 48 00), then a real
        # packet: the packet is dissected whole (the library's parser finds it too), over UDP,
        # TCP and a serial capture
        pkt = encode("shutter")
        data = bytes([0xA8, 0xE5, 0x48, 0x00]) + pkt
        want = json.loads(run("decode", "--json", "--raw", pkt.hex()).stdout)
        host, gcu = [10, 0, 0, 1], [10, 0, 0, 2]
        cases = [
            ("false_udp.pcap", 101, [ip_packet(17, host, gcu, 2338, 2337, data)]),
            ("false_tcp.pcap", 101, [ip_packet(6, host, gcu, 40000, 2332, data, seq=1, ack=1)]),
            ("false_serial.pcap", 147, [b">" + data]),
        ]
        for name, linktype, records in cases:
            pcap = os.path.join(TMP, name)
            write_pcap(pcap, linktype, records)
            trees = xfgcu_trees(tshark_json(pcap))
            self.assertEqual(len(trees), 1, name)
            compare(self, want, trees[0])

    def every_field(self, direction, version):
        """A packet whose every field and reserved byte holds its own value, as large as it takes."""
        blank = run("encode", "--json", "-", stdin=json.dumps({"direction": direction, "version": version})).stdout
        base = json.loads(run("decode", "--json", "--raw", blank.strip()).stdout)
        obj = {"direction": direction, "version": version}
        names = [k for k in base if k not in EXTRAS] + ["reserved_main", "reserved_sub"]
        for i, name in enumerate(names):
            if name.startswith("reserved"):
                tries = [("%02X" % (0xA0 + i)) * n for n in range(1, 9)]
            else:
                big, mid = 0x01020304 * (i + 1) % 0x7FFFFFFF, 0x0102 + 0x0101 * i
                # negative where the field is signed, else the top bit set: a wrong sign shows
                tries = [-big, -mid, -(i + 2), 0x80000000 + i, 0x8000 + i, 0x80 + i]
            for value in tries:
                probe = dict(obj, **{name: value})
                if run("encode", "--json", "--raw", "-", stdin=json.dumps(probe), check=False).returncode == 0:
                    obj = probe
                    break
            else:
                self.fail("no value of %s encodes" % name)
        return bytes.fromhex(run("encode", "--json", "--raw", "-", stdin=json.dumps(obj)).stdout.strip().replace(" ", ""))

    def test_every_field(self):
        packets = [self.every_field(d, v) for d in ("host", "gcu") for v in (1, 2)]
        host, gcu = [10, 0, 0, 1], [10, 0, 0, 2]
        pcap = os.path.join(TMP, "fields.pcap")
        write_pcap(pcap, 101, [ip_packet(17, host, gcu, 2338, 2337, p) for p in packets])
        trees = xfgcu_trees(tshark_json(pcap))
        self.assertEqual(len(trees), len(packets))
        for raw, tree in zip(packets, trees):
            pkt = json.loads(run("decode", "--json", "--raw", raw.hex()).stdout)
            self.assertGreater(sum(1 for k, v in pkt.items() if k not in EXTRAS and v not in (0, "")), 20)
            compare(self, pkt, tree)

    def test_ethernet_and_pcapng(self):
        """tcpdump's Ethernet captures and Wireshark's pcapng are read too."""
        pkt, reply = encode("shutter"), encode("null")
        eth = bytes(12) + b"\x08\x00"
        pcap = os.path.join(TMP, "eth.pcap")
        write_pcap(pcap, 1, [eth + ip_packet(17, [10, 0, 0, 1], [10, 0, 0, 2], 2338, 2337, p) for p in (pkt, reply)])
        ng = os.path.join(TMP, "eth.pcapng")
        subprocess.run(["editcap", "-F", "pcapng", pcap, ng], check=True, capture_output=True)
        for f in (pcap, ng):
            out = packet_lines(run("replay", f, "--json", "--raw").stdout)
            self.assertEqual([o["order_name"] for o in out], ["shutter", "null"])
            self.assertEqual(run("decode", "--json", "--raw", "--file", f).stdout, run("replay", f, "--json", "--raw").stdout)
            self.assertEqual(len(xfgcu_trees(tshark_json(f))), 2)

    def test_serial_user0(self):
        pkt = encode("shutter")
        pcap = os.path.join(TMP, "serial.pcap")
        write_pcap(pcap, 147, [b">" + pkt[:5], b">" + pkt[5:] + pkt[:1], b">" + pkt[1:]])
        trees = xfgcu_trees(tshark_json(pcap))
        self.assertEqual(len(trees), 2)
        compare(self, json.loads(run("decode", "--json", "--raw", pkt.hex()).stdout), trees[0])
        out = packet_lines(run("replay", pcap, "--json", "--raw").stdout)
        self.assertEqual(len(out), 2)


class CaptureFiles(unittest.TestCase):
    def write(self, name, text):
        path = os.path.join(TMP, name)
        with open(path, "wb") as f:
            f.write(text.encode("latin-1"))
        return path

    def rejects(self, body, line, reason):
        path = self.write("bad.cap", "# xfgcu capture 1\n" + body)
        r = run("replay", path, check=False)
        self.assertEqual(r.returncode, 2)
        self.assertEqual(r.stdout, "")
        self.assertEqual(r.stderr.count("\n"), 1, r.stderr)
        self.assertTrue(r.stderr.startswith("xfgcu: %s:%d: " % (path, line)), r.stderr)
        self.assertIn(reason, r.stderr)

    def test_replay_rejections(self):
        self.rejects("-1.000 > A8\n", 2, "negative time")
        self.rejects("0.000 > A8\n0.001 > A8 E5\x00 00\n", 3, "NUL")
        self.rejects("0.000 > A8 G5\n", 2, "hex")
        self.rejects("0.000 > A8 E\n", 2, "hex")
        self.rejects("2.000 > A8\n1.000 < 8A\n", 3, "goes back")
        self.rejects("4294968.000 > A8\n", 2, "too large")
        self.rejects("1.5 > A8\n", 2, "milliseconds")
        self.rejects("0.000 ! A8\n", 2, "'>' or '<'")
        self.rejects("# start yesterday\n", 2, "start time")
        self.rejects("0.000 > A8 ", 2, "hex")  # a line that ends in a space, no newline
        path = self.write("bad17.cap", "# xfgcu capture 17\n")  # the first line, exactly
        r = run("replay", path, check=False)
        self.assertEqual(r.returncode, 2)
        self.assertIn("not an xfgcu capture", r.stderr)
        self.rejects("# start 2026-13-26T10:00:00.123Z\n", 2, "start time")  # month 13
        self.rejects("# start 2026-11-26T24:00:00.123Z\n", 2, "start time")  # hour 24
        self.rejects("# start 2026-11-26T10:00:00.123Z junk\n", 2, "start time")

    def test_start_time(self):
        pkt = run("encode", "null").stdout.strip()
        path = self.write("start.cap", "# xfgcu capture 1\n# start 2026-11-26T10:00:00.123Z\n1.500 > %s\n" % pkt)
        obj = packet_lines(run("replay", path, "--json", "--raw").stdout)[0]
        self.assertEqual(obj["t"], 1.5)
        self.assertEqual(obj["time"], "2026-11-26T10:00:01.623Z")
        old = self.write("old.cap", "# xfgcu capture 1\n0.000 > %s\n" % pkt)  # without a start: still read
        self.assertNotIn("time", packet_lines(run("replay", old, "--json", "--raw").stdout)[0])

    def test_decode_logs(self):
        p, q = run("encode", "shutter").stdout.strip(), run("encode", "null").stdout.strip()
        half = (len(p) // 6) * 3  # on a byte boundary: "A8 E5 "
        log = ("12.345 %s\n[2026-11-26 10:00:00.123] %s\n2026-11-26T10:00:01.5Z %s\n[7.25] %s\n%s\n" %
               (p, q, p[:half], p[half:], q))
        out = packet_lines(run("decode", "--json", "--raw", stdin=log).stdout)
        self.assertEqual([o.get("t", o.get("time")) for o in out],
                         [12.345, "2026-11-26T10:00:00.123", 7.25, 7.25])
        self.assertEqual([o["order_name"] for o in out], ["shutter", "null", "shutter", "null"])
        path = self.write("log.txt", log)
        self.assertEqual(len(packet_lines(run("decode", "--json", "--raw", "--file", path).stdout)), 4)
        cap = self.write("t.cap", "# xfgcu capture 1\n0.250 > %s\n" % p)
        self.assertEqual(packet_lines(run("decode", "--json", "--raw", stdin=open(cap).read()).stdout)[0]["t"], 0.25)
        r = run("decode", stdin="12.345 %s zz\n" % p, check=False)
        self.assertEqual(r.returncode, 2)
        self.assertIn("line 1 column", r.stderr)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
