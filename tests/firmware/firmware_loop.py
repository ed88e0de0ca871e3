#!/usr/bin/env python3
"""Firmware in the loop: the example firmware runs, not only compiles, against the simulator.

The emulator's image of examples/mcu (board_netduinoplus2.c) runs under qemu-system-arm's
netduinoplus2 machine: its USART2 (the gimbal) connected to `xfgcu sim --tcp PORT`, qemu being the
TCP client that reconnects each second, its USART1 (the report) on qemu's standard output. The
firmware runs throughout; the simulator is started and stopped around it, phase by phase:

  normal    the loop comes up: 50 packets/s answered, photos, carrier data once the INS is valid
  stopped   no simulator: the link goes down, the firmware keeps running
  noise     a simulator whose replies carry line noise and lose bytes: the link comes back,
            the firmware counts CRC errors and skipped bytes, photos still succeed
  silent    a simulator that answers nothing: the link goes down again
  failing   a simulator whose shutter fails: the link comes back, the photos fail

The checks read the simulator's JSON log (--json --verbose --stats 1) and the firmware's report
lines, each stamped on arrival with the monotonic clock that the simulator's time_mono uses.

Why TCP and not a pseudo-terminal (`-serial pty` and `xfgcu sim --serial /dev/pts/N`, which work
the same way by hand): with both cores of the host busy, replies through a pty reached the
firmware late and in bursts, and through loopback TCP they did not (docs/performance.md,
"Firmware in the loop").

qemu runs in real time (no -icount), so that the firmware answers the simulator as a board would.
Its emulated SysTick loses ticks, though, the more so on a busy host, so the rate is checked on
the firmware's own clock, the one the client runs on, and on the host's clock against the
firmware clock's speed over the same seconds. No check asks the link never to go stale.

usage: firmware_loop.py --qemu PATH --elf PATH --xfgcu PATH --log DIR
exit 0 when every check holds; 1 with each failed check on standard error.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import threading
import time

PHASES = [  # name, seconds on the firmware's clock, the simulator's fault options (None: no simulator)
    ("normal", 8, []),
    ("stopped", 3, None),
    ("noise", 6, ["--noise", "2", "--drop-bytes", "2"]),
    ("silent", 3, ["--drop", "1000"]),
    ("failing", 4, ["--fail", "shutter=1"]),
]
STRETCH = 4.0  # a phase ends after at most STRETCH times its length (plus 5 s) on the host's clock
FW_RATE = (48.0, 52.0)    # packets/s the firmware sent on its own clock: the client's pacing
HOST_SHARE = (0.8, 1.2)  # what the simulator gets on the host's clock, over 50 x the firmware clock's speed
CLOCK = (0.2, 1.2)         # the firmware clock's speed in host seconds: it loses ticks, never gains
SLACK = 0.3               # s: lines of the two logs are compared in time with this much doubt

SHUTTER = "0x20"  # the order a photo is, as the report names it
FW_LINE = re.compile(r"^xfgcu mcu: (\d+)\.(\d{3}) s: (.*)$")
HEALTH = re.compile(
    r"^link (?P<link>up|stale|down), (?P<rate>\d+) replies/s, (?P<missing>\d+) missing/s, "
    r"(?P<sent>\d+) sent, (?P<received>\d+) received; (?P<crc>\d+) CRC errors, "
    r"(?P<length>\d+) length errors, (?P<skipped>\d+) bytes skipped; commands (?P<ok>\d+) ok, "
    r"(?P<failed>\d+) failed, (?P<timeout>\d+) timeout, (?P<lost>\d+) link lost; "
    r"(?P<send_errors>\d+) send errors, (?P<overruns>\d+) rx overruns, (?P<lines_lost>\d+) report lines lost$")
RESULT = re.compile(r"^order (?P<order>0x[0-9A-F]{2}) (?P<status>ok|failed|timeout|link lost|operating|cancelled) "
                    r"\((?P<packets>\d+) packets?, (?P<ms>\d+) ms\)$")


class Lines:
    """A process's output lines, each with the monotonic time it arrived, copied to a log; and the
    firmware's clock, as the last report line gave it."""

    def __init__(self, stream, log_path, echo=False):
        self.items, self.lock, self.fw = [], threading.Lock(), 0.0
        self.thread = threading.Thread(target=self._read, args=(stream, log_path, echo), daemon=True)
        self.thread.start()

    def _read(self, stream, log_path, echo):
        with open(log_path, "w", encoding="utf-8") as log:
            for raw in stream:
                text = raw.decode("utf-8", "replace").rstrip("\r\n")
                m = FW_LINE.match(text)
                with self.lock:
                    self.items.append((time.monotonic(), text))
                    self.fw = int(m.group(1)) + int(m.group(2)) / 1000.0 if m else self.fw
                log.write(text + "\n")
                log.flush()
                if echo:
                    print(text, flush=True)

    def snapshot(self):
        with self.lock:
            return list(self.items)

    def firmware_seconds(self):
        with self.lock:
            return self.fw


def start_qemu(args, port, seconds):
    """The firmware, USART1 on standard output, USART2 a TCP client of the simulator's port."""
    cmd = ["timeout", "--signal=KILL", str(int(seconds) + 30), args.qemu, "-M", "netduinoplus2",
           "-kernel", args.elf, "-display", "none", "-monitor", "none", "-serial", "stdio",
           "-serial", f"tcp:127.0.0.1:{port},nodelay=on,reconnect=1"]
    proc = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    return proc, Lines(proc.stdout, os.path.join(args.log, "firmware.log"), echo=args.echo)


def start_sim(args, port, seconds, faults):
    """`xfgcu sim --tcp PORT` (0: any free port) for at most `seconds`; returns it running and its
    "listening" event."""
    cmd = [args.xfgcu, "sim", "--tcp", str(port), "--json", "--verbose", "--stats", "1",
           "--duration", str(seconds)] + faults
    proc = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True)
    first = proc.stdout.readline()
    if not first.strip():
        proc.wait(10)
        raise SystemExit(f"firmware_loop: {' '.join(cmd)} exited {proc.returncode}: {proc.stderr.read().strip()}")
    return proc, json.loads(first)


def finish_sim(proc, listening, log_path):
    proc.terminate()  # it prints its totals and exits 0
    out, err = proc.communicate(timeout=15)
    with open(log_path, "w", encoding="utf-8") as log:
        log.write(json.dumps(listening) + "\n" + out + err)
    if proc.returncode != 0:
        raise SystemExit(f"firmware_loop: {' '.join(proc.args)} exited {proc.returncode}: {err.strip()}")
    return [listening] + [json.loads(line) for line in out.splitlines() if line.strip()]


def parse_firmware(items):
    """Report lines as dicts: t (host), fw (firmware seconds), kind, and the fields of the kind."""
    out = []
    for t, text in items:
        m = FW_LINE.match(text)
        if not m:
            continue
        rec = {"t": t, "fw": int(m.group(1)) + int(m.group(2)) / 1000.0, "text": m.group(3)}
        h, r = HEALTH.match(rec["text"]), RESULT.match(rec["text"])
        if h:
            rec.update(kind="health", link=h.group("link"),
                       **{k: int(v) for k, v in h.groupdict().items() if k != "link"})
        elif r:
            rec.update(kind="result", order=r.group("order"), status=r.group("status"))
        elif rec["text"].startswith("link "):
            rec.update(kind="link", link=rec["text"][5:])
        elif rec["text"].startswith("ins "):
            rec.update(kind="ins", valid=rec["text"] == "ins valid")
        else:
            rec.update(kind="other")
        out.append(rec)
    return out


class Checks:
    def __init__(self):
        self.failed, self.passed = [], 0

    def expect(self, ok, what):
        if ok:
            self.passed += 1
        else:
            self.failed.append(what)
        print(f"{'ok  ' if ok else 'FAIL'} {what}", flush=True)


class Phase:
    def __init__(self, name, start, end, events):
        self.name, self.start, self.end, self.events = name, start, end, events
        self.stats = [e for e in events if e.get("event") == "stats"]

    def holds(self, rec, late=SLACK):
        """rec arrived during the phase (or up to `late` s after its end)."""
        return self.start <= rec["t"] <= self.end + late

    def executed(self, order, state=None):
        return [e for e in self.events if e.get("event") == "executed" and e.get("order_name") == order
                and (state is None or e.get("state") == state)]

    def final(self, key):
        return self.stats[-1][key] if self.stats else None


def of_kind(fw, kind, **fields):
    return [r for r in fw if r["kind"] == kind and all(r.get(k) == v for k, v in fields.items())]


def last_before(health, t):
    before = [r for r in health if r["t"] <= t]
    return before[-1] if before else None


def clock_speed(a, b):
    """Firmware seconds per host second between two report lines."""
    return (b["fw"] - a["fw"]) / (b["t"] - a["t"])


def check_boot(c, fw):
    starts = [r for r in fw if r["text"].startswith("started on ")]
    c.expect(len(starts) == 1 and "netduinoplus2" in starts[0]["text"],
             "the firmware started once, on the emulated board, and never again")
    m = re.search(r"a photo every (\d+) ms", starts[0]["text"]) if starts else None
    return int(m.group(1)) if m else 0


def check_alive(c, fw, phases):
    health = of_kind(fw, "health")
    gaps = [b["fw"] - a["fw"] for a, b in zip(health, health[1:])]
    c.expect(len(health) >= 20 and 0.99 <= min(gaps) and max(gaps) <= 1.1,
             f"a health line each second of the firmware's clock throughout ({len(health)} lines, "
             f"{min(gaps) if gaps else 0:.3f} to {max(gaps) if gaps else 0:.3f} s apart)")
    c.expect(bool(health) and health[-1]["t"] > phases[-1].end,
             "the firmware still reports after the last phase")
    if len(health) >= 2:
        speed = clock_speed(health[0], health[-1])  # a wrong clock constant is off by a factor: 10.5 for 16 MHz
        c.expect(CLOCK[0] <= speed <= CLOCK[1], f"the firmware's millisecond tick: {speed:.3f} s per host s")
    c.expect(bool(health) and health[-1]["send_errors"] == 0 and health[-1]["overruns"] == 0
             and health[-1]["lines_lost"] == 0, "no send error, receive overrun or lost report line")


def check_loop(c, fw, normal):
    c.expect(any(normal.holds(r) for r in of_kind(fw, "link", link="up")), "normal: the firmware's link comes up")
    up = [r for r in of_kind(fw, "health", link="up") if normal.holds(r, late=0)]
    if len(up) >= 2 and up[-1]["fw"] - up[0]["fw"] >= 3.0:
        rate = (up[-1]["sent"] - up[0]["sent"]) / (up[-1]["fw"] - up[0]["fw"])
        c.expect(FW_RATE[0] <= rate <= FW_RATE[1], f"normal: the firmware sends {rate:.1f} packets/s on its clock")
    else:
        c.expect(False, f"normal: the link is up for 3 s of health lines ({len(up)} lines)")
    c.expect(bool(up) and max(r["rate"] for r in up) >= 40 and all(r["crc"] == 0 for r in up),
             "normal: the firmware counts 40 replies/s or more, and no CRC error")
    flowing = [s for s in normal.stats if s["packets_in"] > 0][1:]  # from the second: the link is settled
    span = (flowing[0]["time_mono"], flowing[-1]["time_mono"]) if flowing else (0.0, 0.0)
    health = [r for r in of_kind(fw, "health") if span[0] <= r["t"] <= span[1]]
    if len(flowing) >= 3 and len(health) >= 2:
        a, b = flowing[0], flowing[-1]
        rate = (b["packets_in"] - a["packets_in"]) / (b["time_mono"] - a["time_mono"])
        want = 50.0 * clock_speed(health[0], health[-1])
        c.expect(HOST_SHARE[0] <= rate / want <= HOST_SHARE[1],
                 f"normal: the simulator gets {rate:.1f} packets/s, the firmware's clock says {want:.1f}")
    else:
        c.expect(False, f"normal: packets reach the simulator for 3 s ({len(flowing)} stats lines)")
    c.expect(normal.final("replies") == normal.final("packets_in") > 0,
             f"normal: the simulator answers every packet ({normal.final('replies')} of "
             f"{normal.final('packets_in')})")


def check_photos(c, fw, phase, status, least):
    state = 0 if status == "ok" else 1
    sim = len(phase.executed("shutter", state))
    mine = len([r for r in of_kind(fw, "result", order=SHUTTER, status=status) if phase.holds(r, late=1.5)])
    c.expect(sim >= least and mine >= least,
             f"{phase.name}: photos {status}: {sim} executed by the simulator, {mine} reported by the firmware")


def check_results(c, fw, phases):
    """Every execution ends in a result at the firmware, and no result comes without one."""
    ran = {0: sum(p.final("photos") or 0 for p in phases), 1: sum(len(p.executed("shutter", 1)) for p in phases)}
    got = {st: len(of_kind(fw, "result", order=SHUTTER, status=st))
           for st in ("ok", "failed", "timeout", "link lost")}
    c.expect(got["ok"] <= ran[0] and got["failed"] <= ran[1] and ran[0] + ran[1] <= sum(got.values()),
             f"photos: {ran[0]} executed ok and {ran[1]} failing by the simulator; the firmware reports "
             + ", ".join(f"{n} {st}" for st, n in got.items()))


def check_ins(c, fw, normal, later):
    ins = of_kind(fw, "ins")
    c.expect(len(ins) == 1 and ins[0]["valid"] and normal.holds(ins[0]),
             "normal: the stand-in INS becomes valid once, while the simulator runs")
    if len(ins) != 1:
        return
    t = ins[0]["t"]
    steps = list(zip(normal.stats, normal.stats[1:]))
    before = [(a, b) for a, b in steps if b["time_mono"] < t - SLACK and b["packets_in"] > a["packets_in"]]
    after = [(a, b) for a, b in steps if a["time_mono"] > t + SLACK]
    c.expect(bool(before) and all(b["ins_valid_packets"] == 0 for _, b in before),
             f"normal: before the INS is valid, no packet has ins_valid set ({len(before)} s of packets)")
    c.expect(bool(after) and all(b["ins_valid_packets"] - a["ins_valid_packets"] == b["packets_in"] - a["packets_in"]
                                 for a, b in after),
             f"normal: after it, every packet has ins_valid set ({len(after)} s of packets)")
    c.expect(all(p.final("ins_valid_packets") == p.final("packets_in") > 0 for p in later),
             "noise, silent, failing: every packet has ins_valid set")


def check_restart(c, fw, stopped, back):
    down = [r for r in of_kind(fw, "link", link="down") if stopped.holds(r)]
    up = [r for r in of_kind(fw, "link", link="up") if back.holds(r)]
    c.expect(bool(down) and bool(up) and down[0]["t"] < up[0]["t"],
             f"{stopped.name}, {back.name}: the firmware's link goes down, and comes back when the "
             "simulator is started again")


def check_noise(c, fw, noise):
    health = of_kind(fw, "health")
    a, b = last_before(health, noise.start), last_before(health, noise.end + SLACK)
    c.expect(noise.final("noise_bytes") > 0 and noise.final("dropped_bytes") > 0,
             f"noise: the simulator added {noise.final('noise_bytes')} noise bytes, "
             f"dropped {noise.final('dropped_bytes')}")
    c.expect(a is not None and b is not None and b["crc"] > a["crc"] and b["skipped"] > a["skipped"]
             and b["received"] > a["received"],
             "noise: the firmware counts CRC errors and skipped bytes, and still receives replies")


def check_silent(c, fw, silent):
    down = [r for r in of_kind(fw, "link", link="down") if silent.holds(r)]
    last = last_before(of_kind(fw, "health"), silent.end + SLACK)
    c.expect(silent.final("packets_in") > 0 and silent.final("replies") == 0,
             "silent: the firmware keeps sending, the simulator answers nothing")
    c.expect(bool(down) and last is not None and last["link"] == "down" and last["rate"] == 0
             and last["missing"] >= 20, "silent: the firmware's link goes down, and it counts the missing replies")


def check_counts(c, fw):
    last = of_kind(fw, "health")[-1]
    ok, failed = len(of_kind(fw, "result", status="ok")), len(of_kind(fw, "result", status="failed"))
    c.expect(last["ok"] == ok and last["failed"] == failed,
             f"the health line counts the results reported: {last['ok']} ok, {last['failed']} failed")


def cap(seconds):
    """The longest a phase of `seconds` on the firmware's clock may take on the host's."""
    return STRETCH * seconds + 5.0


class Run:
    """The phases in turn, each as long as the firmware's clock says (a starved emulator runs slow,
    and what the checks expect of the firmware is on its clock); qemu starts once the first
    simulator has its port."""

    def __init__(self, args):
        self.args, self.port, self.qemu, self.lines, self.phases = args, 0, None, None, []

    def wait_firmware(self, seconds, start):
        fw0 = self.lines.firmware_seconds() if self.lines else 0.0
        while time.monotonic() - start < cap(seconds) and (
                self.lines is None or self.lines.firmware_seconds() < fw0 + seconds):
            time.sleep(0.05)

    def phase(self, name, seconds, faults):
        print(f"--- {name}: {seconds} s, " + (" ".join(["xfgcu sim"] + faults) if faults is not None
                                                else "no simulator"), flush=True)
        start = time.monotonic()
        if faults is None:
            self.wait_firmware(seconds, start)
            self.phases.append(Phase(name, start, time.monotonic(), []))
            return
        proc, listening = start_sim(self.args, self.port, cap(seconds) + 5.0, faults)
        self.port = listening["port"]  # the same port each time: qemu reconnects to it
        if self.qemu is None:
            self.qemu, self.lines = start_qemu(self.args, self.port, sum(cap(p[1]) for p in PHASES))
        self.wait_firmware(seconds, start)
        events = finish_sim(proc, listening, os.path.join(self.args.log, f"sim-{name}.log"))
        self.phases.append(Phase(name, start, time.monotonic(), events))

    def stop(self):
        if self.qemu is not None:
            self.qemu.terminate()  # timeout(1) passes it on to qemu
            self.qemu.wait(10)
            self.lines.thread.join(5)


def run(args):
    os.makedirs(args.log, exist_ok=True)
    r = Run(args)
    try:
        for name, seconds, faults in PHASES:
            r.phase(name, seconds, faults)
        r.wait_firmware(2, time.monotonic())  # the last health line, and a photo the last stop cut short
    finally:
        r.stop()
    return r.phases, parse_firmware(r.lines.snapshot())


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--qemu", required=True)
    ap.add_argument("--elf", required=True)
    ap.add_argument("--xfgcu", required=True)
    ap.add_argument("--log", required=True, help="directory for the firmware's and the simulator's logs")
    args = ap.parse_args()
    args.echo = True
    t0 = time.monotonic()
    try:
        phases, fw = run(args)
    except (OSError, subprocess.TimeoutExpired) as e:
        print(f"firmware_loop: {e}", file=sys.stderr)
        return 1
    p = {ph.name: ph for ph in phases}
    c = Checks()
    photo_ms = check_boot(c, fw)
    c.expect(0 < photo_ms <= 2000, f"a test image: a photo every {photo_ms} ms (2000 at most)")
    check_alive(c, fw, phases)
    check_loop(c, fw, p["normal"])
    check_photos(c, fw, p["normal"], "ok", 2)
    check_ins(c, fw, p["normal"], [p["noise"], p["silent"], p["failing"]])
    check_restart(c, fw, p["stopped"], p["noise"])
    check_noise(c, fw, p["noise"])
    check_photos(c, fw, p["noise"], "ok", 1)
    check_silent(c, fw, p["silent"])
    check_restart(c, fw, p["silent"], p["failing"])
    check_photos(c, fw, p["failing"], "failed", 1)
    check_results(c, fw, phases)
    check_counts(c, fw)
    print(f"firmware_loop: {c.passed} checks passed, {len(c.failed)} failed, {time.monotonic() - t0:.1f} s; "
          f"logs in {args.log}", flush=True)
    for what in c.failed:
        print(f"firmware_loop: FAILED: {what}", file=sys.stderr)
    return 1 if c.failed else 0


if __name__ == "__main__":
    sys.exit(main())
