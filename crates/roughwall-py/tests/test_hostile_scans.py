"""Hostile scans (issue 42): what is no regular file, files that never end, and height fields
of magnitudes no wall has end quickly with a result or a one-line ValueError or OSError naming
the file or the cause, never a hang, an abort or a panic. Each runs in a child interpreter
under limits (address space, CPU time, a timeout), so that a regression fails the test
instead of hanging or killing the suite."""

import json
import os
import pathlib
import re
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

SRC = pathlib.Path(__file__).resolve().parents[1] / "src"


def run_child(script, *args, timeout):
    """`script` in a child interpreter with `args`; its completed process. A child still
    running after `timeout` s fails the test (it is killed, the suite goes on)."""
    try:
        return subprocess.run([sys.executable, "-c", textwrap.dedent(script), *map(str, args)],
                              capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        pytest.fail(f"still running after {timeout} s: {args}")


READ = """
    import sys
    import roughwall
    kw = eval(sys.argv[2])
    try:
        roughwall.read_scan(sys.argv[1], **kw)
    except BaseException as e:
        print(f"{type(e).__name__}: {e}")
    else:
        print("read")
"""


def test_a_fifo_is_refused_not_waited_on(tmp_path):
    fifo = tmp_path / "scan.txt"
    os.mkfifo(fifo)
    for kw in ({}, dict(format="gwyddion_text"), dict(format="matrix", pixel_m=(1e-6, 1e-6), height_unit_m=1e-6)):
        p = run_child(READ, fifo, repr(kw), timeout=20)
        assert p.returncode == 0, p.stderr[-2000:]
        line = p.stdout.strip()
        assert line.startswith(f"OSError: {fifo}: ") and "FIFO" in line, (kw, line)


@pytest.mark.parametrize("path,kw", [("/dev/zero", dict(format="sur")), ("/dev/zero", {}),
                                     ("/dev/urandom", dict(format="opd")), ("/", {})])
def test_a_device_or_a_directory_ends_quickly_with_an_error(path, kw):
    t0 = time.monotonic()
    p = run_child(READ, path, repr(kw), timeout=20)
    assert p.returncode == 0, p.stderr[-2000:]
    line = p.stdout.strip()
    assert re.match(r"(OSError|ValueError): ", line) and path in line, line
    assert time.monotonic() - t0 < 15


CARD = """
    import json, resource, sys, time
    resource.setrlimit(resource.RLIMIT_AS, (4 << 30, 4 << 30))
    resource.setrlimit(resource.RLIMIT_CPU, (20, 20))
    import numpy as np
    import roughwall
    path, how = sys.argv[1], sys.argv[2]
    t0 = time.monotonic()
    try:
        if how == "scan":
            card = roughwall.wall_card(roughwall.read_scan(path), diameters_m=[100e-6, 500e-6])
        else:
            card = roughwall.wall_card(path, diameters_m=[100e-6, 500e-6])
    except (ValueError, OSError) as e:
        out = dict(error=type(e).__name__, message=str(e))
    else:
        wall = card["wall"]
        numbers = [card["parameters"]["sq_m"], *(wall.values() if wall else [])]
        out = dict(result=True, finite=bool(np.isfinite(numbers).all()), rows=len(card["diameters"]))
    out["seconds"] = time.monotonic() - t0
    print(json.dumps(out))
"""


def gwyddion(path, rows, width="4 um", height="3 um"):
    """A Gwyddion text export: its header, then one line of heights (m) per row."""
    lines = ["# Channel: Z", f"# Width: {width}", f"# Height: {height}", "# Value units: m"]
    lines += [" ".join(repr(float(v)) for v in row) for row in rows]
    path.write_text("\n".join(lines) + "\n")
    return path


def hostile_scans(tmp_path):
    """(name, file, what the message names besides the file when refused, must it give a
    result)."""
    rng = np.random.default_rng(7)
    rough = rng.normal(scale=1e-7, size=(3, 4))
    a = np.zeros((3, 4))
    a[2, 2], a[2, 3] = 3e299, 3e300
    return [
        ("a-3e300-in-last-row", gwyddion(tmp_path / "a.txt", a), "height", False),
        ("b-height-1e303-m", gwyddion(tmp_path / "b.txt", [[0.0, 1e-6], [2e-6, 0.0]], "2 um", "1e303 m"),
         "dy", False),
        ("c-heights-1e308", gwyddion(tmp_path / "c.txt", np.tile([1e308, -1e308], (3, 2))), "height", False),
        ("d-heights-1e307", gwyddion(tmp_path / "d.txt", 1e307 * (1 + rng.random((3, 4)))), "height", False),
        ("e-offset-1e300", gwyddion(tmp_path / "e.txt", rough + 1e300), "height", False),
        ("f-pixel-1e300-m", gwyddion(tmp_path / "f.txt", rough, "4e300 m", "3e300 m"), "dx", False),
        ("g-strip-1m-by-1um", gwyddion(tmp_path / "g.txt", rng.normal(scale=1e-7, size=(100_000, 2)),
                                       "2 m", "0.1 m"), None, True),
        ("h-pixel-1m-by-1nm", gwyddion(tmp_path / "h.txt", rng.normal(scale=1e-9, size=(8, 8)), "8 m", "8 nm"),
         None, True),
    ]


def test_hostile_scans_end_with_a_result_or_an_error_naming_the_cause(tmp_path):
    failures = []
    t0 = time.monotonic()
    for name, path, cause, result in hostile_scans(tmp_path):
        # The strip's card takes the longest: once, from its path.
        for how in ("path",) if result and name.startswith("g") else ("scan", "path"):
            p = run_child(CARD, path, how, timeout=40)
            where = f"{name} ({how})"
            if p.returncode != 0:
                failures.append(f"{where}: the child died (status {p.returncode}): {p.stderr[-1500:]}")
                continue
            out = json.loads(p.stdout.strip().splitlines()[-1])
            if "error" in out:
                m = out["message"]
                named = path.name in m if how == "path" else (cause is not None and cause in m)
                if result:
                    failures.append(f"{where}: no result: {out['error']}: {m}")
                elif not named or "\n" in m or "internal error" in m:
                    failures.append(f"{where}: {out['error']} does not name the cause: {m}")
            elif not out["finite"] or out["rows"] != 3:
                failures.append(f"{where}: a result that is not clean: {out}")
            if result and out["seconds"] > 15:
                failures.append(f"{where}: {out['seconds']:.1f} s for an 8 × 8 scan or a 2 × 10⁵ strip")
    assert not failures, "\n".join(failures)
    assert time.monotonic() - t0 < 90


def entries(text):
    """(name, body) of every #[pyfunction] and every #[pymethods] method but the getters."""
    lines = text.splitlines()
    attrs, in_methods, out = [], False, []
    for i, line in enumerate(lines):
        stripped = line.strip()
        if stripped == "#[pymethods]":
            in_methods = True
        elif line == "}":
            in_methods = False
        if stripped.startswith("#["):
            attrs.append(stripped)
            continue
        m = re.match(r"(\s*)(pub )?fn (\w+)", line)
        if m and (any(a.startswith("#[pyfunction") for a in attrs)
                  or (in_methods and not any(a.startswith("#[getter") for a in attrs))):
            start = next(j for j in range(i, len(lines)) if lines[j].endswith("{")) + 1
            end = next(j for j in range(start, len(lines)) if lines[j] == m.group(1) + "}")
            out.append((m.group(3), "\n".join(lines[start:end])))
        if stripped and not stripped.startswith("///"):
            attrs = []
    return out


def test_every_entry_runs_inside_guarded():
    """Every #[pyfunction] and every #[pymethods] method but the getters (which only copy
    fields) runs its whole body inside errors::guarded: the checks, the library's work and
    the conversion of its results, so that a panic is a RuntimeError, never a
    PanicException unwinding into the interpreter."""
    names = []
    for rs in sorted(SRC.glob("*.rs")):
        for name, body in entries(rs.read_text()):
            names.append(name)
            code = [ln.strip() for ln in body.splitlines() if ln.strip() and not ln.strip().startswith("//")]
            assert code and code[0].startswith("guarded(") and code[-1] == "})", (
                f"{rs.name}: fn {name} does not run its body inside errors::guarded")
    assert sorted(names) == ["deterministic", "measured_wall_table", "new", "read_scan", "rebound", "stochastic", "surface",
                             "wall_card"]
