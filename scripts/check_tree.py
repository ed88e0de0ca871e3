#!/usr/bin/env python3
"""Fail when git tracks a file that does not belong in the repository.

What is refused, in every tracked file:
- an object file, archive, shared library or executable binary, known by its first bytes (ELF,
  ar, Mach-O, PE/COFF) or by its name (.o .obj .a .so .dylib .dll .exe .elf .bin);
- a file with the executable bit that is not a script (no "#!" first line);
- a file over 1 MiB, unless it is generated data listed in ALLOWED_LARGE below, with the reason;
- a test source (a .c, .h, .cpp or .py file under tests/, tools/tests/, python/tests/ or fuzz/)
  over 1000 lines: the next engineer should be able to read a test file whole, so a long one is
  split by concern (tests/README.md says how the folders are cut).

Run from anywhere in the clone: scripts/check_tree.py. Exit 0 when clean, 1 with one line per
offending file otherwise; when clean, it names the longest test source. `scripts/check_tree.py
--self-test` shows, in a scratch repository, that each kind of file above is refused and that
sources, scripts, fuzz inputs, a test source of exactly 1000 lines and a long non-test source are
not.
"""
import os
import subprocess
import sys
import tempfile

MAX_BYTES = 1 << 20
# Generated data that may be larger than MAX_BYTES: path -> why it is tracked. None today.
ALLOWED_LARGE: dict[str, str] = {}

MAGIC = [
    (b"\x7fELF", "an ELF object or executable"),
    (b"!<arch>\n", "an ar archive (static library)"),
    (b"\xfe\xed\xfa\xce", "a Mach-O binary"),
    (b"\xfe\xed\xfa\xcf", "a Mach-O binary"),
    (b"\xce\xfa\xed\xfe", "a Mach-O binary"),
    (b"\xcf\xfa\xed\xfe", "a Mach-O binary"),
    (b"MZ", "a DOS/Windows executable"),
]
BINARY_SUFFIXES = (".o", ".obj", ".a", ".so", ".dylib", ".dll", ".exe", ".elf", ".bin", ".pyc")
MAX_TEST_LINES = 1000
TEST_DIRS = ("tests/", "tools/tests/", "python/tests/", "fuzz/")
TEST_SUFFIXES = (".c", ".h", ".cpp", ".py")


def tracked():
    """(mode, path) of every file in the index."""
    out = subprocess.run(["git", "ls-files", "-s", "-z"], check=True, capture_output=True).stdout
    for entry in out.split(b"\0"):
        if entry:
            meta, path = entry.split(b"\t", 1)
            yield meta.split()[0].decode(), path.decode()


def test_lines(path):
    """The number of lines of @path if it is a test source, else None."""
    if not (path.startswith(TEST_DIRS) and path.endswith(TEST_SUFFIXES)):
        return None
    with open(path, "rb") as f:
        data = f.read()
    return data.count(b"\n") + (1 if data and not data.endswith(b"\n") else 0)


def problem(mode, path):
    """Why @path should not be tracked, or None."""
    if mode == "120000" or mode == "160000":  # a symbolic link or a submodule: no content here
        return None
    with open(path, "rb") as f:
        head = f.read(8)
    for magic, what in MAGIC:
        # "MZ" alone is two common letters: a PE file also says "PE\0\0" further in.
        if head.startswith(magic) and (magic != b"MZ" or is_pe(path)):
            return what
    if path.endswith(BINARY_SUFFIXES):
        return "a build product, by its name"
    if mode == "100755" and not head.startswith(b"#!"):
        return "executable but not a script (no #! line)"
    size = os.path.getsize(path)
    if size > MAX_BYTES and path not in ALLOWED_LARGE:
        return f"{size} bytes, over the {MAX_BYTES}-byte limit (list generated data in ALLOWED_LARGE)"
    lines = test_lines(path)
    if lines is not None and lines > MAX_TEST_LINES:
        return f"a test source of {lines} lines, over {MAX_TEST_LINES}: split it by concern"
    return None


def is_pe(path):
    with open(path, "rb") as f:
        data = f.read(4096)
    if len(data) < 0x40:
        return False
    at = int.from_bytes(data[0x3C:0x40], "little")
    return data[at:at + 4] == b"PE\0\0"


def self_test():
    """Each refused kind is refused, and ordinary files are not."""
    with tempfile.TemporaryDirectory() as tmp:
        os.chdir(tmp)
        subprocess.run(["git", "init", "-q"], check=True)
        files = {
            "ok.c": (b"int main(void) { return 0; }\n", 0o644),
            "ok.sh": (b"#!/bin/sh\necho hi\n", 0o755),
            "fuzz/input": (b"\xa8\xe5\x48\x00\x01MZ\x7fELF", 0o644),  # magic bytes later on: data
            "prog": (b"\x7fELF\x02\x01\x01" + bytes(100), 0o755),
            "lib.a": (b"!<arch>\n" + bytes(10), 0o644),
            "x.o": (b"whatever", 0o644),
            "run": (b"echo no shebang\n", 0o755),
            "big.dat": (bytes(MAX_BYTES + 1), 0o644),
            "tests/long.c": (b"int x;\n" * (MAX_TEST_LINES + 1), 0o644),
            "python/tests/test_long.py": (b"x = 1\n" * MAX_TEST_LINES + b"y = 2", 0o644),  # no final newline
            "tests/edge.c": (b"int x;\n" * MAX_TEST_LINES, 0o644),
            "src/long.c": (b"int x;\n" * (MAX_TEST_LINES + 1), 0o644),
        }
        for path, (data, mode) in files.items():
            os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
            with open(path, "wb") as f:
                f.write(data)
            os.chmod(path, mode)
        subprocess.run(["git", "add", "--", *files], check=True)
        refused = {path for mode, path in tracked() if problem(mode, path)}
    want = {"prog", "lib.a", "x.o", "run", "big.dat", "tests/long.c", "python/tests/test_long.py"}
    if refused != want:
        print(f"check_tree: self-test: refused {sorted(refused)}, expected {sorted(want)}", file=sys.stderr)
        return 1
    print(f"check_tree: self-test passed ({len(want)} files refused, {len(files) - len(want)} kept)")
    return 0


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    os.chdir(subprocess.run(["git", "rev-parse", "--show-toplevel"], check=True, capture_output=True,
                            text=True).stdout.strip())
    bad = [(path, why) for mode, path in tracked() if (why := problem(mode, path))]
    for path, why in bad:
        print(f"check_tree: {path}: {why}", file=sys.stderr)
    if not bad:
        links = ("120000", "160000")
        longest = max((test_lines(path) or 0, path) for mode, path in tracked() if mode not in links)
        print("check_tree: no binaries, build products, oversized files or test sources over "
              f"{MAX_TEST_LINES} lines are tracked (the longest test source: {longest[1]}, {longest[0]} lines)")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
