#!/usr/bin/env python3
"""Regenerate docs/performance.md from the benchmarks: every figure of the page comes from a
command of the repository, run here (or, with --reuse, from its last run's record under build/).

  scripts/perf_page.py            run the benchmarks, then write docs/performance.md
  scripts/perf_page.py --reuse    use build/bench/results.txt and build/mcu/results.txt when they
                                  exist instead of running scripts/bench.sh and
                                  scripts/mcu_size.sh again

What it runs: scripts/bench.sh (parser and packer instructions, frames, latency in bytes),
scripts/firmware_loop.sh (the firmware example under qemu), test_client_reorder with
XF_REORDER_FULL=1 (the link judgement, simulated time),
scripts/mcu_size.sh (Cortex-M4 flash and RAM), scripts/parser_loc.py (lines of code), the client
benchmark (bench/xf_client_bench.c: latency, CPU, heap) and scripts/bench_send.sh (the program's
`send` time) from a Release build in build/perf. What it reads when present: build/fuzz/campaign.txt
(the last `scripts/fuzz.sh long` campaign) and build/test-time.txt (the last `scripts/test.sh`
run). Times depend on the machine; instruction counts and sizes do not.
"""
import os
import platform
import re
import subprocess
import sys
from datetime import datetime, timezone

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
OUT = os.path.join(ROOT, "docs", "performance.md")
KINDS = ["valid", "noisy", "uart4", "uart3", "adversarial", "hostile", "dense", "storm", "h0run", "pairs",
         "cpairs", "mixed", "mixed79", "credit", "chain"]
REALISTIC = ["valid", "noisy", "uart4", "uart3"]
CHUNKS = ["1", "2", "3", "4", "8", "16", "64", "4096"]
TABLES = [("nibble", "16-entry table (default)"), ("t256", "256-entry table (`XF_CRC_TABLE_256=1`)")]
# The speed targets of the parser (clean stream, Ir/byte at 1 / 16 / >= 64 bytes per call).
SPEED = {"nibble": (60, 35, 30), "t256": (45, 25, 20)}
BOUND = 150
NOISY = 1.3
# `xfgcu send`'s time per link: a link that keeps order (TCP, serial) sends the command in the
# second packet; over UDP the client first watches six question-and-answer periods for replies out
# of turn before it runs a command (docs/protocol.md section 7.4), about 120 ms at 50 Hz.
SEND_MS = {"tcp": 30, "udp": 150}
SEND_WHY = {"udp": " (six periods judging the link first)"}


def run(cmd, **kw):
    print("perf_page.py: " + " ".join(cmd), file=sys.stderr)
    return subprocess.run(cmd, cwd=ROOT, check=True, stdout=subprocess.PIPE, text=True, **kw).stdout


def records(path):
    """`name value...` lines of a results file, as a list of word lists."""
    with open(os.path.join(ROOT, path)) as f:
        return [line.split() for line in f if line.strip()]


def figure(recs, *key):
    """The first record that starts with key: its remaining words."""
    for r in recs:
        if tuple(r[:len(key)]) == key:
            return r[len(key):]
    raise KeyError(" ".join(key))


def ok(value, limit):
    return "met" if float(value) <= float(limit) else "**over**"


def machine():
    cpu = "unknown CPU"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    gcc = run(["gcc", "--version"]).splitlines()[0]
    return "%s, `nproc` = %d, %s, %s" % (cpu, os.cpu_count() or 0, platform.platform(terse=True), gcc)


def client_figures():
    """Build the client benchmark and the program (Release, build/perf) and run them."""
    run(["cmake", "-S", ".", "-B", "build/perf", "-DCMAKE_BUILD_TYPE=Release", "-DXFGCU_BUILD_BENCH=ON",
         "-DXFGCU_BUILD_TESTS=OFF", "-DXFGCU_BUILD_EXAMPLES=OFF", "-DXFGCU_BUILD_FUZZ=OFF"])
    run(["cmake", "--build", "build/perf", "--parallel", "2", "--target", "xfgcu_client_bench", "xfgcu"])
    bench = "build/perf/bench/xfgcu_client_bench"
    return {"latency": run([bench, "latency", "1000"]), "cpu": run([bench, "cpu", "3"]),
            "alloc": run([bench, "alloc"]), "send": run(["scripts/bench_send.sh", "build/perf/tools/xfgcu", "30"])}


def loop_figures():
    """The firmware example under qemu against the simulator (client_figures' program), and the
    client's link judgement over simulated links (the fake clock: the figures do not depend on the
    machine), in scripts/test.sh's Debug build."""
    fw = run(["scripts/firmware_loop.sh", "--xfgcu", os.path.join(ROOT, "build/perf/tools/xfgcu")])
    run(["cmake", "-S", ".", "-B", "build/gcc", "-DCMAKE_BUILD_TYPE=Debug", "-DCMAKE_C_COMPILER=gcc",
         "-DXFGCU_BUILD_PYTHON=ON"])
    run(["cmake", "--build", "build/gcc", "--parallel", "2", "--target", "test_client_reorder"])
    reorder = run(["build/gcc/tests/client/test_client_reorder"], env=dict(os.environ, XF_REORDER_FULL="1"))
    return {"firmware": fw, "reorder": reorder}


def loop_rows(lp):
    """The firmware loop's checks and command times; the link judgement's lines."""
    fw = lp["firmware"].splitlines()
    ms = sorted(int(x) for x in re.findall(r"order 0x20 \w+ \(1 packet, (\d+) ms\)", lp["firmware"]))
    out = ["", "## Firmware in the loop (QEMU)", "",
           "`scripts/firmware_loop.sh` (also the ctest `firmware_loop`): the firmware example built for QEMU's "
           "`netduinoplus2` board (an emulated STM32F405) runs the client at 50 Hz over its emulated UART, "
           "connected by TCP to `xfgcu sim`, through five phases (normal, simulator stopped, noise and "
           "dropped bytes, silence, failing photos). The checks, each with what it measured:", "", "```"]
    out += [l for l in fw if l.startswith(("ok ", "FAIL"))]
    out += [l.split("; logs in")[0] for l in fw if re.match(r"firmware_loop: \d+ checks", l)]
    out += ["```"]
    if ms:
        out += ["", "A photo's time on the firmware's clock, submit to result: %d commands, %d to %d ms, median %d ms "
                "(one packet each)." % (len(ms), ms[0], ms[-1], ms[len(ms) // 2])]
    out += ["", "## Link judgement", "",
            "`XF_REORDER_FULL=1 test_client_reorder` (simulated links on the client's injected clock; "
            "`docs/protocol.md` section 7.4): links that delay replies by up to 60 ms at random (jitter) or "
            "deliver some twice, with the client's defaults and with the reorder bound fixed at 0 (what a "
            "client that trusts the link would do). A false ok is a command reported done on another "
            "command's reply; run twice, a command the GCU executed twice.", "", "```"]
    out += [l.strip() for l in lp["reorder"].splitlines() if "seeds:" in l or l.strip().startswith("clean link")]
    out += ["```"]
    return out


def optional(path):
    p = os.path.join(ROOT, path)
    return records(path) if os.path.exists(p) else None


def stream_notes():
    """The streams' descriptions, from the benchmark's own header comment (one place)."""
    text = open(os.path.join(ROOT, "bench", "xfgcu_bench.c")).read()
    block = text[text.index(" * Streams"):text.index(" *   Which crafted stream")]
    rows, cur = [], None
    for line in block.splitlines()[1:]:
        m = re.match(r"^ \*   (\w+)\s+(.*)$", line)
        if m:
            cur = [m.group(1), m.group(2).strip()]
            rows.append(cur)
        elif cur is not None:
            cur[1] += " " + line.lstrip(" *").strip()
    return rows


def parser_tables(b):
    out = []
    for t, name in TABLES:
        out += ["", "**%s**: Ir/byte at 1 / 2 / 3 / 4 / 8 / 16 / 64 / 4096 bytes per call; frames found / "
                "intact inserted (512 KiB, 4096 per call); `given_up`; worst delay in bytes over the chunk sizes." % name,
                "", "| stream | " + " | ".join(CHUNKS) + " | frames | given_up | delay |",
                "|---|" + "---:|" * (len(CHUNKS) + 3)]
        for k in KINDS:
            irs = [figure(b, "ir", t, k, c)[0] for c in CHUNKS]
            found, inserted, given, delay = figure(b, "frames", t, k)
            out.append("| `%s` | %s | %s / %s | %s | %s |" % (k, " | ".join(irs), found, inserted, given, delay))
        floor = [figure(b, "ir", t, "floor", c)[0] for c in CHUNKS]
        out.append("| valid floor | %s | | | |" % " | ".join(floor))
        worst = figure(b, "worst", t)
        out += ["", "CRC alone (`xf_crc16_update`, 4096 per call): %s Ir/byte. Receive path (parse + "
                "`xf_frame_gcu` + `xf_feedback_decode`, valid, 4096 per call): %s Ir/byte. Costliest: **%s** "
                "Ir/byte (`%s`, %s bytes per call). Pack / unpack: %s / %s Ir/packet." %
                (figure(b, "crc", t)[0], figure(b, "decode", t)[0], worst[0], worst[1].split(",")[0],
                 worst[1].split(",")[1], figure(b, "pack", t)[0], figure(b, "unpack", t)[0])]
    return out


def summary(b, m, loc, ci):
    rows = []
    for t, name in TABLES:
        one, sixteen, big = SPEED[t]
        v = [figure(b, "ir", t, "valid", c)[0] for c in ("1", "16", "64", "4096")]
        verdict = "met" if (float(v[0]) <= one and float(v[1]) <= sixteen and max(float(v[2]), float(v[3])) <= big) \
            else "**over**"
        rows.append("| parser, clean stream, %s, 1 / 16 / 64 / 4096 bytes per call | <= %d / %d / %d / %d Ir/byte | "
                    "%s | %s | `scripts/bench.sh` |" % (name, one, sixteen, big, big, " / ".join(v), verdict))
        r = figure(b, "noisy_ratio", t)
        rows.append("| parser, realistic noise (noisy, uart4, uart3), %s | <= %.1f x clean at the same chunk size | "
                    "%s x (%s, %s per call) | %s | `scripts/bench.sh` |" %
                    (t, NOISY, r[0], r[1].split(",")[0], r[1].split(",")[1], ok(r[0], NOISY)))
        w = figure(b, "worst", t)
        rows.append("| parser, any stream, any chunk size (the bound of `docs/codec.md`), %s | <= %d Ir/byte | %s "
                    "(`%s`, %s per call) | %s | `scripts/bench.sh` (fails above) |" %
                    (t, BOUND, w[0], w[1].split(",")[0], w[1].split(",")[1], ok(w[0], BOUND)))
    lost = [k for k in REALISTIC if int(figure(b, "frames", "nibble", k)[0]) < int(figure(b, "frames", "nibble", k)[1])]
    delays = [figure(b, "frames", t, k)[3] for t, _ in TABLES for k in KINDS]
    rows.append("| every intact frame of the realistic streams, at every chunk size | all | %s | %s | "
                "`scripts/bench.sh` (fails otherwise) |" % ("all" if not lost else "missed in " + ", ".join(lost),
                                                           "met" if not lost else "**over**"))
    rows.append("| added latency | 0 bytes | %s on every stream, every chunk size | %s | `scripts/bench.sh` (fails "
                "otherwise) |" % (max(delays, key=int), "met" if all(d == "0" for d in delays) else "**over**"))
    hf = figure(b, "frames", "nibble", "hostile")
    rows.append("| frames on the `hostile` stream (noise biased to headers, false headers before half the frames) "
                "| (none) | %s of %s, `given_up` %s | | `scripts/bench.sh` |" % (hf[0], hf[1], hf[2]))
    af = figure(b, "frames", "nibble", "adversarial")
    rows.append("| frames on the crafted `adversarial` stream | (none) | %s of %s, `given_up` %s | | "
                "`scripts/bench.sh` |" % (af[0], af[1], af[2]))
    rows.append("| parser + CRC source | <= 300 lines of code, no function over 40 lines | %s lines; longest "
                "function %s lines (`%s`) | %s | `scripts/lint.sh` (fails above) |" %
                (loc["total"], loc["longest"][1], loc["longest"][0],
                 "met" if int(loc["total"]) <= 300 and int(loc["longest"][1]) <= 40 else "**over**"))
    for key, what, limit in (("parser_flash_nibble", "parser + CRC, Cortex-M4 -Os, 16-entry table", 1536),
                             ("parser_flash_t256", "parser + CRC, Cortex-M4 -Os, 256-entry table", 2048),
                             ("parser_state_255", "parser state, `XF_PACKET_MAX_LEN` 255", 300),
                             ("firmware_flash", "codec + client flash, firmware example", 8192),
                             ("firmware_ram", "codec + client RAM per gimbal, firmware example", 512)):
        v = figure(m, key)[0]
        rows.append("| %s | <= %d B | %s B | %s | `scripts/mcu_size.sh` (fails above) |" % (what, limit, v, ok(v, limit)))
    return rows


def client_summary(c):
    """The client's rows of the summary, read from the benchmarks' own output."""
    rows = []
    lat = {m.group(1): m.group(2) for m in re.finditer(r"^(\w+)\s+[\d.]+\s+[\d.]+\s+([\d.]+)\s", c["latency"], re.M)}
    rows.append("| reply-to-callback latency, loopback, p99 | <= 200 us | %s us | %s | `xfgcu_client_bench latency 1000` |" %
                (" / ".join("%s %s" % (k, v) for k, v in lat.items()), "met" if all(float(v) <= 200 for v in lat.values())
                 else "**over** in this run (a shared, loaded machine)"))
    m = re.search(r"^\s*64 gimbals:\s+([\d.]+) %.*?\(([\d.]+) us", c["cpu"], re.M)
    if m:
        rows.append("| 64 gimbals at 50 Hz from one thread | <= 5 %% of one core | %s %% (%s us of CPU per gimbal per "
                    "packet) | %s | `xfgcu_client_bench cpu 3` |" % (m.group(1), m.group(2), ok(m.group(1), 5)))
    m = re.search(r"steady state .*: (\d+)", c["alloc"])
    if m:
        rows.append("| heap allocations, client and simulator, steady state | 0 | %s | %s | `xfgcu_client_bench alloc` |"
                    % (m.group(1), "met" if m.group(1) == "0" else "**over**"))
    for link, v in re.findall(r"send shutter, (\w+) loopback.*median ([\d.]+) ms", c["send"]):
        limit = SEND_MS.get(link, 30)
        rows.append("| `xfgcu send shutter`, start to exit, %s loopback, 50 Hz, median | < %d ms%s | %s ms | %s | "
                    "`scripts/bench_send.sh` |" % (link, limit, SEND_WHY.get(link, ""), v, ok(v, limit)))
    return rows


def client_rows(c):
    out = ["", "```"] + c["latency"].strip().splitlines() + ["```", "", "```"] + c["cpu"].strip().splitlines() + \
        ["```", "", "```"] + c["alloc"].strip().splitlines() + c["send"].strip().splitlines() + ["```"]
    return out


def fuzz_rows(campaign):
    if campaign is None:
        return ["", "No campaign is recorded in this build tree (`build/fuzz/campaign.txt`): run "
                "`scripts/fuzz.sh long [SECONDS]`, then this script."]
    head = {r[0]: r[1] for r in campaign if r[0] in ("commit", "date", "seconds")}
    out = ["", "The last campaign, `scripts/fuzz.sh long %s` (parser of `%s`, %s), one binary after the other:" %
           (head.get("seconds", "?"), head.get("commit", "?"), head.get("date", "?")), "",
           "| binary | seconds | executions | new inputs | result |", "|---|---:|---:|---:|---|"]
    for r in campaign:
        if r[0] == "binary":
            out.append("| `%s` | %s | %s | %s | %s |" % (r[1], head.get("seconds", "?"), r[2], r[3],
                                                       "no crash, no violated invariant" if r[4] == "ok" else r[4]))
    return out


def main():
    reuse = sys.argv[1:] == ["--reuse"]
    if sys.argv[1:] and not reuse:
        sys.exit(__doc__)
    if not (reuse and os.path.exists(os.path.join(ROOT, "build/bench/results.txt"))):
        run(["scripts/bench.sh"])
    if not (reuse and os.path.exists(os.path.join(ROOT, "build/mcu/results.txt"))):
        run(["scripts/mcu_size.sh"])
    b, m = records("build/bench/results.txt"), records("build/mcu/results.txt")
    loc_out = run(["scripts/parser_loc.py"])
    loc = {"total": re.search(r"^lines total (\d+)", loc_out, re.M).group(1),
           "longest": re.search(r"^longest (\w+) (\d+)", loc_out, re.M).groups(),
           "files": re.findall(r"^lines (\S+/\S+) (\d+)", loc_out, re.M)}
    c = client_figures()
    lp = loop_figures()
    campaign, ci = optional("build/fuzz/campaign.txt"), optional("build/test-time.txt")
    page = render(b, m, loc, c, lp, campaign, ci)
    with open(OUT, "w") as f:
        f.write("\n".join(page) + "\n")
    print("perf_page.py: wrote docs/performance.md (%d lines)" % len(page), file=sys.stderr)


def render(b, m, loc, c, lp, campaign, ci):
    commit = "`%s`" % figure(b, "commit")[0]
    if figure(m, "commit")[0] != figure(b, "commit")[0]:
        commit += " (the sizes at `%s`)" % figure(m, "commit")[0]
    when = datetime.now(timezone.utc).strftime("%Y-%m-%d")
    p = ["# Performance", "",
         "<!-- Generated by scripts/perf_page.py from the benchmarks: do not edit; run the script. -->", "",
         "Measured at commit %s on %s, on %s. Every figure comes from the command named with it, "
         "which `scripts/perf_page.py` runs (`scripts/test.sh`, what CI runs, runs them too and fails on the "
         "gates marked so). Instruction counts (valgrind's `Ir`, the parser's own instructions inside "
         "`xf_parser_feed`) and sizes are deterministic; times depend on the machine, a shared one here." %
         (commit, when, machine()), "", "## Summary against the targets", "",
         "| what | target | measured | verdict | command |", "|---|---|---|---|---|"]
    p += summary(b, m, loc, ci)
    p += client_summary(c)
    if ci is not None:
        h = {r[0]: r[1] for r in ci}
        p.append("| the whole test suite, `scripts/test.sh` (what CI runs) | < 15 min on 2 cores | %s s (commit `%s`, "
                 "%s, %s cores) | %s | `.ci/run` |" % (h["seconds"], h["commit"], h["date"], h["cores"],
                                                      ok(h["seconds"], 900)))
    p += ["", "## The parser", "",
          "Instructions per byte inside `xf_parser_feed` (`scripts/bench.sh`: callgrind, the Ir inside the function "
          "over a 512 KiB stream, per byte, gcc `-O2`, the program's symbols bound at start-up). The `valid floor` row is a reference that "
          "only searches every byte for `h0`, stores and CRCs each frame (`xb_floor_feed`): what the clean "
          "stream's work costs without any rule. The realistic streams (valid, noisy, uart4, uart3) must lose no "
          "intact frame; the others are built to cost the most or to crowd the slots, and lose frames by design "
          "(`given_up` counts the headers not followed, `docs/codec.md` rule 3)."]
    p += parser_tables(b)
    p += ["", "### Streams", "", "`xfgcu_bench gen KIND N_BYTES FILE` (deterministic; a shorter stream is a prefix "
          "of a longer one); the descriptions are `bench/xfgcu_bench.c`'s.", "", "| kind | content |", "|---|---|"]
    p += ["| `%s` | %s |" % (k, d) for k, d in stream_notes()]
    p += ["", "## MCU: flash and RAM", "",
          "`scripts/mcu_size.sh`, `arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb -Os`. The parser linked alone is a "
          "stub that feeds it, linked with the codec's translation unit and `--gc-sections`: the sizes of the "
          "functions and tables defined in `xf_parser.h`, `xf_crc.h` and `xf_crc_tables.h` (the C library's "
          "`memcpy`, `memmove`, `memchr`, `memset` apart). The firmware is `examples/mcu` (its options: "
          "`XF_PACKET_MAX_LEN=84`, 4 slots, a queue of 2), its codec and client read from the linker map.", "",
          "| what | bytes |", "|---|---:|"]
    for key, what in (("parser_flash_nibble", "parser + CRC linked alone, 16-entry table"),
                      ("parser_flash_t256", "parser + CRC linked alone, 256-entry table"),
                      ("parser_state_255", "`sizeof(xf_parser)`, `XF_PACKET_MAX_LEN=255`"),
                      ("parser_state_84", "`sizeof(xf_parser)`, `XF_PACKET_MAX_LEN=84`"),
                      ("client_state_255", "`sizeof(xf_client)`, parser included, `XF_PACKET_MAX_LEN=255`"),
                      ("client_state_84", "`sizeof(xf_client)`, parser included, `XF_PACKET_MAX_LEN=84`"),
                      ("codec_text", "the codec compiled once (every function, before `--gc-sections`)"),
                      ("firmware_text", "firmware example, whole image (text)"),
                      ("firmware_bss", "firmware example, whole image (bss, UART rings included)"),
                      ("firmware_flash", "firmware example: codec + client flash"),
                      ("firmware_parser_flash", "firmware example: of which the parser and CRC"),
                      ("firmware_ram", "firmware example: RAM of its one `xf_client`, parser included"),
                      ("riscv_client_text", "RISC-V preset (rv32imac, no C library): the client's archive"),
                      ("riscv_codec_text", "RISC-V preset: the codec's archive")):
        p.append("| %s | %s |" % (what, figure(m, key)[0]))
    p += ["", "Source: %s lines of code in the parser and CRC (%s; comments, blank lines and the generated tables "
          "apart; `scripts/parser_loc.py`)." % (loc["total"], ", ".join("`%s` %s" % (os.path.basename(f), n)
                                                                        for f, n in loc["files"]))]
    p += ["", "## Client and simulator", "",
          "`build/perf/bench/xfgcu_client_bench` (Release): `latency 1000`, the reply-to-callback latency with the "
          "simulator on its own thread (target p99 <= 200 us); `cpu 3`, the CPU time of the thread driving the "
          "clients at 50 Hz over loopback UDP (target: 64 gimbals <= 5 % of a core); `alloc`, heap allocations in "
          "steady state (target 0; also the ctest `client_no_heap`). `scripts/bench_send.sh`: `xfgcu send shutter` "
          "from start to exit against the simulator on loopback, over UDP and TCP."]
    p += client_rows(c)
    p += loop_rows(lp)
    p += ["", "## Fuzzing", "",
          "Two libFuzzer harnesses (`fuzz/`), each also built as `_alt` (`XF_CRC_TABLE_256=1`, "
          "`XF_PACKET_MAX_LEN=84`, `XF_NO_LIBC=1`) and `_slots1` (`XF_PARSER_SLOTS=1`), all with ASan, UBSan and "
          "`XF_ASSERT` on. After every `xf_parser_feed` call, in chunk sizes the input chooses, they check the "
          "return value and `consumed`, that the six counters and `xf_parser_pending()` equal the reference "
          "model's (`tests/parser_ref.h`), that each frame is the model's next one, ends where the call's "
          "consumed bytes end and lies in the parser, and the codec's round trips on it. `fuzz_parser_crcfix` also "
          "checks that every intact packet it inserted comes out when `given_up` is 0. `scripts/fuzz.sh smoke` "
          "(CI) replays `fuzz/corpus/` and `fuzz/regressions/` and fuzzes 30 s per harness; plain `ctest` replays "
          "the saved inputs with any compiler; a crash leaves its reproducer in `build/fuzz/artifacts/`, to be "
          "copied to `fuzz/regressions/`. `scripts/mutate.sh` (CI) applies named mutants of the parser's rules "
          "and requires the tests to kill each."]
    p += fuzz_rows(campaign)
    p += ["", "## How to reproduce", "", "```sh",
          "scripts/perf_page.py          # every figure of this page, then the page",
          "scripts/bench.sh              # the parser tables (both CRC tables): %s s at this run" % figure(b, "seconds")[0],
          "scripts/firmware_loop.sh      # the firmware example under qemu against xfgcu sim",
          "XF_REORDER_FULL=1 build/gcc/tests/client/test_client_reorder   # the link judgement's figures",
          "scripts/bench.sh profile      # where the instructions go, per function (-g builds)",
          "scripts/mcu_size.sh           # Cortex-M4 and RISC-V sizes, with their gates",
          "scripts/parser_loc.py         # lines of code",
          "scripts/fuzz.sh long 600      # a fuzz campaign, recorded in build/fuzz/campaign.txt",
          "```"]
    return p


if __name__ == "__main__":
    main()
