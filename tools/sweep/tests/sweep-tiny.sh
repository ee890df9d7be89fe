#!/usr/bin/env bash
# The tiny sweep of ctest (sweep.tiny): 2 meshes x 2 modelisations of the Lame ring, one of which
# does not exist. Checks the table's columns, the errors against hand-computed ones, that the
# failing runs are rows (not the end of the sweep), --report, and a parameter no file assigns.
set -euo pipefail
stella=$1
tiny=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$stella" sweep "$tiny/tiny.sweep" --output-dir "$out" --no-plot 2>"$out/progress.txt" ||
  fail "the sweep ended with $? (failed runs must not end it)"
grep -q "sweep: 6/6 runs" "$out/progress.txt" || fail "no final progress line: $(cat "$out/progress.txt")"

/usr/bin/python3 - "$out" <<'PY'
import csv, os, sys
out = sys.argv[1]
rows = list(csv.DictReader(open(os.path.join(out, "sweep.csv"))))
header = open(os.path.join(out, "sweep.csv")).readline().strip().split(",")
expected = ["run", "series", "label", "MODEL", "UNIT", "mesh_size", "status", "finished", "repeats",
            "wall_s", "cpu_s", "time_s", "time_of", "peak_mem_mb", "steps", "newton_iter", "contact_iter", "geom_iter",
            "snl_numbering_s", "snl_assembly_s", "snl_factorisation_s", "snl_solve_s", "snl_post_s",
            "snl_other_s", "snl_total_s", "error", "error_of", "err:u_r(a)", "err:u_r(b)", "files", "pareto"]
def check(ok, what):
    if not ok:
        sys.exit("FAIL: " + what)
check(header == expected, "columns %s" % header)
check(len(rows) == 4, "%d rows, expected 4" % len(rows))
check([r["label"] for r in rows] == ["QUAD8 MODEL=D_PLAN", "QUAD8 MODEL=D_PLAM", "TRIA3 MODEL=D_PLAN",
                                     "TRIA3 MODEL=D_PLAM"], "labels")
# Hand-computed errors, from the values these meshes give (testcases/lame_cylinder/lame.comm's
# VALE_CALC): |u - u_ref| / |u_ref| with u_ref(a) = 9.533333333333335e-4, u_ref(b) = 6.066666666666668e-4.
hand = {0: (abs(0.000953314478122818 - 9.533333333333335e-4) / 9.533333333333335e-4,
            abs(0.0006066582851718222 - 6.066666666666668e-4) / 6.066666666666668e-4),
        2: (abs(0.0009559833521780194 - 9.533333333333335e-4) / 9.533333333333335e-4,
            abs(0.000605293948834362 - 6.066666666666668e-4) / 6.066666666666668e-4)}
for i, (ea, eb) in hand.items():
    r = rows[i]
    check(r["status"] == "OK" and r["finished"] == "yes" and r["repeats"] == "2", "row %d: %s" % (i, r))
    check(abs(float(r["err:u_r(a)"]) - ea) <= 1e-4 * ea, "row %d err u_r(a) %s, hand %g" % (i, r["err:u_r(a)"], ea))
    check(abs(float(r["err:u_r(b)"]) - eb) <= 1e-4 * eb, "row %d err u_r(b) %s, hand %g" % (i, r["err:u_r(b)"], eb))
    check(r["error"] == r["err:u_r(a)"] and r["error_of"] == "u_r(a)", "row %d: the error shown" % i)
    check(float(r["wall_s"]) > 0 and float(r["cpu_s"]) > 0 and float(r["peak_mem_mb"]) > 1, "row %d: measures" % i)
    check(r["files"] == "", "row %d: the files of a good run are removed" % i)
for i in (1, 3):
    r = rows[i]
    check(r["status"] == "<F>_SYNTAX_ERROR" and r["finished"] == "no", "row %d: %s" % (i, r))
    check(r["repeats"] == "1", "row %d: a failed run is not repeated" % i)
    check(r["error"] == "" and r["pareto"] == "", "row %d: a failed run has no error, is off the front" % i)
    check(os.path.exists(os.path.join(out, r["files"], "r1", "lame.mess")), "row %d: its message file is kept" % i)
# QUAD8 has the smallest error: nothing can beat it, it is on the front whatever the timings.
check(rows[0]["pareto"] == "yes", "the most accurate run is on the Pareto front")
PY
grep -q "error 1.97782e-05: \*\*QUAD8 MODEL=D_PLAN\*\*" "$out/sweep.md" || fail "the front in words: $(cat "$out/sweep.md")"

# -j 2: two runs at a time give the same rows (statuses, repeats, errors) as one at a time.
"$stella" sweep "$tiny/tiny.sweep" -j 2 --output-dir "$out/j2" --no-plot 2>/dev/null || fail "-j 2 ended with $?"
/usr/bin/python3 - "$out" <<'PY'
import csv, os, sys
def rows(d):
    keep = ("label", "status", "repeats", "error", "err:u_r(a)", "err:u_r(b)")
    return [[r[k] for k in keep] for r in csv.DictReader(open(os.path.join(d, "sweep.csv")))]
one, two = rows(sys.argv[1]), rows(os.path.join(sys.argv[1], "j2"))
if one != two:
    sys.exit("FAIL: -j 2 differs from -j 1:\n%s\n%s" % (one, two))
PY

# --report: the tables (and the figure, with matplotlib) again from sweep.csv, without running.
cp "$out/sweep.csv" "$out/before.csv"
rm "$out/sweep.md"
rm -rf "$out/runs"
if /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
  "$stella" sweep --report "$out" 2>/dev/null || fail "--report ended with $?"
  test -s "$out/sweep.png" || fail "--report drew no figure"
else
  echo "note: no matplotlib for /usr/bin/python3: --report checked with --no-plot"
  "$stella" sweep --report "$out" --no-plot 2>/dev/null || fail "--report ended with $?"
fi
cmp -s "$out/sweep.csv" "$out/before.csv" || fail "--report changed the CSV"
grep -q "^| 1 | QUAD8 MODEL=D_PLAN | OK |" "$out/sweep.md" || fail "--report: no table in sweep.md"
grep -q "^Tables and figure redrawn from" "$out/sweep.md" || fail "--report: no note in sweep.md"
# A second --report keeps the words before the table (the command, the load) of the first.
echo "Written by a sweep on a machine with a load of 1.0." >"$out/sweep.md.new"
sed -n '/^| run |/,$p' "$out/sweep.md" >>"$out/sweep.md.new"
mv "$out/sweep.md.new" "$out/sweep.md"
"$stella" sweep --report "$out" --no-plot 2>/dev/null || fail "--report ended with $?"
test "$(head -1 "$out/sweep.md")" = "Written by a sweep on a machine with a load of 1.0." || fail "--report lost the preamble"
test ! -e "$out/runs" || fail "--report ran the study again"

# A parameter no command file assigns is refused before any run, naming it (exit 65).
set +e
msg=$("$stella" sweep "$tiny/tiny.sweep" --vary 'NU=0.2,0.3' --output-dir "$out/bad" 2>&1)
code=$?
set -e
test "$code" = 65 || fail "a parameter nobody assigns: exit $code, expected 65: $msg"
grep -q "parameter NU is set (0.2) but no command file assigns it on a line of its own before DEBUT()" <<<"$msg" ||
  fail "message: $msg"
# MESH is assigned after DEBUT() only (a concept): a parameter of that name is refused the same way.
set +e
msg=$("$stella" sweep "$tiny/tiny.sweep" --vary "MESH='a','b'" --output-dir "$out/bad2" 2>&1)
code=$?
set -e
test "$code" = 65 || fail "a parameter named as a concept after DEBUT(): exit $code: $msg"
test ! -e "$out/bad/runs/001/r1/lame.mess" || fail "a run started despite the bad parameter"
# The mesh command: run once per mesh in the sweep file's folder with {MESH} and {mesh} replaced;
# a mesh that cannot be made is a row (MESH_FAILED), not the end of the sweep.
"$stella" sweep "$tiny/mesh.sweep" --output-dir "$out/mesh" --no-plot 2>"$out/mesh.txt" ||
  fail "the mesh sweep ended with $?: $(cat "$out/mesh.txt")"
/usr/bin/python3 - "$out/mesh" <<'PY'
import csv, os, sys
out = sys.argv[1]
rows = list(csv.DictReader(open(os.path.join(out, "sweep.csv"))))
def check(ok, what):
    if not ok:
        sys.exit("FAIL: " + what)
check([r["series"] for r in rows] == ["ring_tria3.msh", "ring_missing.msh"], "series named by MESH_FILE: %s" % rows)
check(rows[0]["status"] == "OK", "the copied TRIA3 mesh runs: %s" % rows[0])
# the TRIA3 ring's error (hand-computed above): the generated mesh replaced unit 20
ea = abs(0.0009559833521780194 - 9.533333333333335e-4) / 9.533333333333335e-4
check(abs(float(rows[0]["err:u_r(a)"]) - ea) <= 1e-4 * ea, "the mesh of unit 20 is the generated one")
check(rows[1]["status"] == "MESH_FAILED" and rows[1]["finished"] == "no" and rows[1]["repeats"] == "0",
      "a mesh command that fails: %s" % rows[1])
cmd = open(os.path.join(out, "meshes", "mesh_1.msh.command")).read()
check(cmd.startswith("cp ../../../../testcases/lame_cylinder/ring_tria3.msh ") and cmd.strip().endswith("mesh_1.msh"),
      "the mesh command as run: " + cmd)
PY
grep -q "the mesh command failed" "$out/mesh.txt" || fail "the failed mesh is not reported: $(cat "$out/mesh.txt")"
# An external series: a command run per point (fake_external.sh standing for CalculiX), timed as
# stella's runs are, its errors in the same columns; its failing point is a row (exit 3).
"$stella" sweep "$tiny/external.sweep" --output-dir "$out/ext" --no-plot 2>"$out/ext.txt" ||
  fail "the external sweep ended with $?: $(cat "$out/ext.txt")"
/usr/bin/python3 - "$out/ext" <<'PY'
import csv, os, sys
out = sys.argv[1]
rows = list(csv.DictReader(open(os.path.join(out, "sweep.csv"))))
def check(ok, what):
    if not ok:
        sys.exit("FAIL: " + what)
check([r["label"] for r in rows] == ["QUAD8 MODEL=D_PLAN", "QUAD8 MODEL=D_PLAM", "FAKE MODEL=D_PLAN",
                                     "FAKE MODEL=D_PLAM"], "labels %s" % [r["label"] for r in rows])
r = rows[2]
ea = abs(9.5e-4 - 9.533333333333335e-4) / 9.533333333333335e-4  # 3.4965e-3 by hand; the CSV has 6 digits
check(r["status"] == "OK" and r["finished"] == "yes" and r["repeats"] == "2", "external OK row: %s" % r)
check(abs(float(r["err:u_r(a)"]) - ea) <= 1e-5 * ea, "external error %s, hand %g" % (r["err:u_r(a)"], ea))
check(r["error"] == r["err:u_r(a)"] and r["err:u_r(b)"] == "", "external error columns: %s" % r)
check(float(r["wall_s"]) >= 0.2, "the external run is timed (it sleeps 0.2 s): %s" % r["wall_s"])
check(rows[0]["status"] == "OK" and rows[0]["pareto"] == "yes", "stella's row beside it: %s" % rows[0])
r = rows[3]
check(r["status"] == "exit 3" and r["finished"] == "no" and r["repeats"] == "1" and r["error"] == "",
      "a failing external run is a row: %s" % r)
log = open(os.path.join(out, r["files"], "r1", "log")).read()
cmd = open(os.path.join(out, r["files"], "r1", "command")).read()
check("fake: no model D_PLAM" in log, "the external run's log is kept: " + log)
check(cmd.startswith("./fake_external.sh D_PLAM /") and cmd.strip().endswith("/r1/out"), "the command as run: " + cmd)
PY
# Interrupted (SIGINT to the sweep): no new run, the table of what was done, exit 6. 4 points x
# 1000 repeats (the failing points are not repeated: 2002 runs) cannot end before the signal, which
# comes as soon as the first run is reported (polled, not slept: no machine is too fast for it); the
# run under way then ends normally (the signal went to the sweep only).
"$stella" sweep "$tiny/tiny.sweep" --repeats 1000 --output-dir "$out/stop" --no-plot 2>"$out/stop.txt" &
pid=$!
for _ in $(seq 600); do
  grep -q "QUAD8 MODEL=D_PLAN (1/1000): OK" "$out/stop.txt" 2>/dev/null && break
  sleep 0.1
done
kill -INT "$pid"
set +e
wait "$pid"
code=$?
set -e
test "$code" = 6 || fail "an interrupted sweep: exit $code, expected 6: $(tail -3 "$out/stop.txt")"
grep -q "sweep: interrupted: no new run" "$out/stop.txt" || fail "no word of the interruption"
/usr/bin/python3 - "$out/stop" <<'PY'
import csv, os, sys
rows = list(csv.DictReader(open(os.path.join(sys.argv[1], "sweep.csv"))))
if len(rows) != 4 or rows[-1]["status"] != "NOT_RUN" or rows[0]["status"] != "OK":
    sys.exit("FAIL: the table of an interrupted sweep: %s" % [(r["label"], r["status"], r["repeats"]) for r in rows])
PY
grep -q "^\*\*Interrupted\*\*" "$out/stop/sweep.md" || fail "sweep.md does not say it was interrupted"
echo "sweep.tiny: OK"
