"""Running fmi2sim in the tests: its command line with a clear-error check, under resource limits,
and hostile FMUs made from the built ones (never stored). Shared by the fmi2sim test files."""
import os
import pathlib
import re
import resource
import signal
import subprocess
import zipfile


ASAN_BUILD = "asan" in str(os.environ.get("RW_BUILD_DIR", ""))


def run(exe, *args, check=True):
    proc = subprocess.run([str(exe), *map(str, args)], capture_output=True, text=True, timeout=300)
    if check:
        assert proc.returncode == 0, proc.stderr
    return proc


def assert_one_clear_error(proc, *needles):
    """Non-zero exit, exactly one 'fmi2sim: error:' line holding every needle, no sanitizer report."""
    assert proc.returncode != 0, proc.stderr
    errors = [line for line in proc.stderr.splitlines() if line.startswith("fmi2sim: error:")]
    assert len(errors) == 1, proc.stderr
    for needle in needles:
        assert str(needle) in errors[0], (needle, proc.stderr)
    for report in ("Sanitizer", "runtime error", "Segmentation", "Traceback"):
        assert report not in proc.stderr, proc.stderr


SO = "binaries/linux64/RockingWall.so"


MD = "modelDescription.xml"


# the FMU's own count, as the committed model description declares it
NZ_DECLARED = re.search(r'numberOfEventIndicators="\d+"',
                        (pathlib.Path(__file__).resolve().parents[2] / "fmu_src" / "models" / "RockingWall" / "fmi2"
                         / MD).read_text()).group(0)


def limited(limits):
    """A preexec_fn setting resource limits, with SIGXFSZ ignored so that a write over the
    file-size limit fails with EFBIG (what a full disk does) instead of killing the process."""
    def preexec():
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        for what, value in (limits or {}).items():
            resource.setrlimit(what, (value, value))
    return preexec


def run_limited(exe, *args, limits=None, env=None, timeout=120, **kw):
    return subprocess.run([str(exe), *map(str, args)], capture_output=True, text=True, timeout=timeout,
                          preexec_fn=limited(limits), env=env, **kw)


def memory_cap():
    """Bound the address space where the sanitizer (which reserves terabytes) is not in use, so that
    an old fmi2sim that allocates what a hostile file says cannot take the machine down."""
    return {} if ASAN_BUILD else {resource.RLIMIT_AS: 4 << 30}


def hostile_fmu(src, dst, md=None, entries=None, drop=()):
    """A copy of the FMU src with the model description rewritten by md(text), entries added or
    replaced ({name: bytes or a callable writing into a zip member}), and entries dropped."""
    entries = dict(entries or {})
    with zipfile.ZipFile(src) as zin, zipfile.ZipFile(dst, "w", zipfile.ZIP_DEFLATED) as zout:
        for info in zin.infolist():
            if info.filename in drop or info.filename in entries:
                continue
            data = zin.read(info.filename)
            if info.filename == MD and md:
                data = md(data.decode()).encode()
            zout.writestr(info, data)
        for name, data in entries.items():
            if callable(data):
                with zout.open(name, "w", force_zip64=True) as member:
                    data(member)
            else:
                zout.writestr(name, data)
    return dst


def tmp_env(tmp_path):
    """TMPDIR of its own, so that the test can see what fmi2sim unpacks and leaves behind."""
    tdir = tmp_path / "tmpdir"
    tdir.mkdir(exist_ok=True)
    return dict(os.environ, TMPDIR=str(tdir)), tdir


def leftovers(folder):
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*"))
