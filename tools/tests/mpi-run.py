#!/usr/bin/python3
"""The mpi label (issue 21, doc/parallel.md): one study under mpirun, or the failure of one process.

  mpi-run.py STELLA MPIRUN serial EXPORT DIR           the serial run (the reference), into DIR
  mpi-run.py STELLA MPIRUN N EXPORT DIR SERIAL_DIR     mpirun -n N: diagnostic OK, "MPI processes: N"
                                                       in the message file, and every TEST_RESU value
                                                       equal to the serial run's to 1e-8 relative
  mpi-run.py STELLA MPIRUN failure EXPORT DIR          rank 1 of 2 fails alone (STELLA_MPI_FAIL_RANK=1):
                                                       every process ends, with that rank's diagnostic,
                                                       well before the timeout (no hang)
"""
import os
import pathlib
import subprocess
import sys
import time

RELATIVE = 1e-8  # MUMPS on N processes sums the entries and eliminates in another order


def launcher(mpirun, n):
    words = [mpirun, "-n", str(n), "--oversubscribe"]
    if os.geteuid() == 0:
        words.append("--allow-run-as-root")
    return words


def run(command, out_dir, timeout, extra_env=None):
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", **(extra_env or {}))
    out_dir.mkdir(parents=True, exist_ok=True)
    start = time.monotonic()
    done = subprocess.run(command, capture_output=True, text=True, timeout=timeout, env=env)
    return done, time.monotonic() - start


def computed_values(resu):
    """The VALE_CALC column of every TEST_RESU line, in order."""
    values = []
    for line in resu.read_text().splitlines():
        words = line.split()
        if words and words[0] in ("OK", "NOOK"):
            values.append((words[2], float(words[-3])))
    return values


def compare(serial_dir, out_dir):
    serial = sorted(serial_dir.glob("*.resu"))
    if not serial:
        sys.exit(f"no .resu in {serial_dir}")
    failures = 0
    for ref in serial:
        got = out_dir / ref.name
        a, b = computed_values(ref), computed_values(got)
        if len(a) != len(b) or not a:
            sys.exit(f"{got}: {len(b)} TEST_RESU values, the serial run has {len(a)}")
        # A value the study tests against 0 (a shear stress of the patch test) is rounding noise of
        # its field: it is compared relative to the largest value of the same name in the file.
        largest = {}
        for name, x in a:
            largest[name] = max(largest.get(name, 0.0), abs(x))
        for (name, x), (_, y) in zip(a, b):
            scale = max(abs(x), abs(y), largest[name], 1e-300)
            if abs(x - y) > RELATIVE * scale:
                print(f"{ref.name} {name}: serial {x!r}, MPI {y!r}")
                failures += 1
        print(f"{ref.name}: {len(a)} values equal to {RELATIVE:g} relative")
    if failures:
        sys.exit(f"{failures} values differ")


def main():
    stella, mpirun, mode, export, out_dir = sys.argv[1:6]
    out_dir = pathlib.Path(out_dir)
    base = [stella, "run", export, "--quiet", "--output-dir", str(out_dir)]
    if mode == "serial":
        done, _ = run(base + ["--work-dir", str(out_dir / "work")], out_dir, 900)
        print(done.stderr)
        sys.exit(0 if "stella: diagnostic OK" in done.stderr else 1)
    if mode == "failure":
        done, seconds = run(launcher(mpirun, 2) + base, out_dir, 240, {"STELLA_MPI_FAIL_RANK": "1"})
        print(done.stderr[-3000:])
        if done.returncode == 0:
            sys.exit("the run ended well although rank 1 failed")
        if "fault injected on MPI rank 1" not in done.stderr or "MPI rank 1 of 2" not in done.stderr:
            sys.exit("rank 1's diagnostic is not on the standard error")
        print(f"every process stopped after {seconds:.1f} s, exit code {done.returncode}")
        return
    n = int(mode)
    done, seconds = run(launcher(mpirun, n) + base + ["--work-dir", str(out_dir / "work")], out_dir, 900)
    print(done.stderr[-2000:])
    if "stella: diagnostic OK" not in done.stderr:
        sys.exit(f"mpirun -n {n}: the run did not end OK")
    mess = next(out_dir.glob("*.mess")).read_text()
    if f"MPI processes: {n}" not in mess:
        sys.exit(f"the message file does not say 'MPI processes: {n}'")
    compare(pathlib.Path(sys.argv[6]), out_dir)
    print(f"mpirun -n {n}: {seconds:.1f} s")


if __name__ == "__main__":
    main()
