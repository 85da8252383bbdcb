#!/usr/bin/env bash
# `beltdyn run MODEL -o DIR --hdf5` (issue 6 "Large runs") on
# examples/flat_belt_drive.yaml: DIR/tension.h5 holds /t_s [ntimes] and
# /s_m, /tension_N, /speed_mps [ntimes x nelements], extendible in time,
# where ntimes is the number of history.csv rows and nelements summary.json's
# "nodes"; the first tension values equal tension.csv's (5 significant
# digits); units and model attributes are present; no temporary file is
# left; without --hdf5 no tension.h5 is written. Needs h5dump (hdf5-tools).
set -u
: "${BELTDYN:?BELTDYN must name the built beltdyn}"
EXAMPLES="${EXAMPLES:-$(cd "$(dirname "$0")/../../examples" && pwd)}"
if ! command -v h5dump >/dev/null 2>&1; then
    echo "FAIL h5dump not found (install hdf5-tools: scripts/bootstrap)"; exit 1
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
out="$tmp/out"

if ! "$BELTDYN" run "$EXAMPLES/flat_belt_drive.yaml" -o "$out" --hdf5 --quiet >"$tmp/stdout" 2>"$tmp/stderr"; then
    echo "FAIL beltdyn run --hdf5 exited nonzero"; cat "$tmp/stderr"; exit 1
fi
[ -f "$out/tension.h5" ] || { echo "FAIL no $out/tension.h5"; ls -la "$out"; exit 1; }
h5dump -H "$out/tension.h5" >"$tmp/header.txt" 2>&1 || { echo "FAIL h5dump -H"; cat "$tmp/header.txt"; exit 1; }
h5dump -d /tension_N -s "0,0" -c "1,3" "$out/tension.h5" >"$tmp/first.txt" 2>&1 \
    || { echo "FAIL h5dump -d /tension_N"; cat "$tmp/first.txt"; exit 1; }
h5dump -a /tension_N/units -a /t_s/units -a /s_m/units -a /speed_mps/units -a /model \
    "$out/tension.h5" >"$tmp/attrs.txt" 2>&1 || { echo "FAIL h5dump -a"; cat "$tmp/attrs.txt"; exit 1; }

"$BELTDYN" run "$EXAMPLES/flat_belt_drive.yaml" -o "$tmp/plain" --quiet >/dev/null 2>&1

python3 - "$out" "$tmp" <<'PY'
import csv, json, os, re, sys
out, tmp = sys.argv[1], sys.argv[2]
fails = []
def check(cond, what, detail=""):
    print(("ok   " if cond else "FAIL ") + what + ("" if cond else ": " + str(detail)))
    if not cond:
        fails.append(what)

summary = json.load(open(os.path.join(out, "summary.json")))
nelem = summary["nodes"]
with open(os.path.join(out, "history.csv")) as f:
    ntimes = sum(1 for _ in csv.reader(f)) - 1
header = open(os.path.join(tmp, "header.txt")).read()

# DATASET "name" { ... DATASPACE SIMPLE { ( dims ) / ( maxdims ) }
spaces = {}
for m in re.finditer(r'DATASET "([^"]+)" \{\s*DATATYPE\s+(\S+)\s*DATASPACE\s+SIMPLE \{ \( ([^)]*) \) / \( ([^)]*) \) \}', header):
    spaces[m.group(1)] = (m.group(2), [d.strip() for d in m.group(3).split(",")],
                          [d.strip() for d in m.group(4).split(",")])
check(sorted(spaces) == ["s_m", "speed_mps", "t_s", "tension_N"],
      "the four datasets /t_s /s_m /tension_N /speed_mps", sorted(spaces))
check(ntimes > 1, "history.csv has rows", ntimes)
if "t_s" in spaces:
    typ, dims, maxd = spaces["t_s"]
    check(dims == [str(ntimes)], "/t_s is [ntimes = %d]" % ntimes, dims)
    check(maxd == ["H5S_UNLIMITED"], "/t_s is extendible", maxd)
    check(typ == "H5T_IEEE_F64LE", "/t_s is double", typ)
for name in ("s_m", "tension_N", "speed_mps"):
    if name not in spaces:
        continue
    typ, dims, maxd = spaces[name]
    check(dims == [str(ntimes), str(nelem)], "/%s is [ntimes x nelements] = [%d x %d]" % (name, ntimes, nelem), dims)
    check(maxd == ["H5S_UNLIMITED", str(nelem)], "/%s is extendible along time" % name, maxd)
    check(typ == "H5T_IEEE_F64LE", "/%s is double" % name, typ)

first = open(os.path.join(tmp, "first.txt")).read()
m = re.search(r"DATA \{\s*\(0,0\):\s*([^\n}]*)", first)
h5vals = [float(v) for v in m.group(1).replace(",", " ").split()] if m else []
with open(os.path.join(out, "tension.csv")) as f:
    rows = list(csv.DictReader(f))
csvvals = [float(r["tension_N"]) for r in rows[:3]]
check(len(h5vals) == 3, "h5dump -s 0,0 -c 1,3 gives three tension values", first)
same = len(h5vals) == 3 and all(abs(a - b) <= 5e-5 * max(abs(b), 1e-9) for a, b in zip(h5vals, csvvals))
check(same, "the first three tensions equal tension.csv's (5 significant digits)", (h5vals, csvvals))

attrs = open(os.path.join(tmp, "attrs.txt")).read()
for unit in ('"s"', '"m"', '"N"', '"m/s"'):
    check(unit in attrs, "a dataset has units %s" % unit, attrs[:400])
check('"%s"' % summary["model"] in attrs, "the root attribute model is the model's name", summary["model"])

check(not any(n.startswith(".") for n in os.listdir(out)), "no temporary files left", os.listdir(out))
check(not os.path.exists(os.path.join(tmp, "plain", "tension.h5")), "without --hdf5 no tension.h5")
check(os.path.exists(os.path.join(tmp, "plain", "summary.json")), "the run without --hdf5 completed")
sys.exit(1 if fails else 0)
PY
