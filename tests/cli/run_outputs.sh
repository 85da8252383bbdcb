#!/usr/bin/env bash
# The output contract of `beltdyn run` (cli.md "`run` outputs") on
# examples/flat_belt_drive.yaml (a speed drive, no takeup) and
# examples/vertical_loop.yaml (a gravity takeup, no drive): every key of
# summary.json with its type, every probe and pulley, the exact CSV headers,
# history rows at the output interval from t = 0 to the duration, tension.csv
# with one row per node at every output time, envelope.csv with s increasing
# in [0, belt_length_m], no temporary files left, no progress line when stderr
# is not a terminal, --quiet accepted, ./out as the default DIR.
set -u
: "${BELTDYN:?BELTDYN must name the built beltdyn}"
# absolute, so that it still works after a cd
case "$BELTDYN" in */*) BELTDYN="$(cd "$(dirname "$BELTDYN")" && pwd)/$(basename "$BELTDYN")" ;; esac
EXAMPLES="${EXAMPLES:-$(cd "$(dirname "$0")/../../examples" && pwd)}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/lib/tally.sh"

# the python checker: argv = DIR, then the expectations as JSON; prints one
# "ok ..." or "FAIL ..." line per check
cat >"$tmp/check.py" <<'PY'
import csv, json, math, os, sys

out, exp = sys.argv[1], json.loads(sys.argv[2])
label = exp["label"]
results = []

def check(cond, what, detail=""):
    results.append((bool(cond), what, detail))
    return bool(cond)

def is_num(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)

def is_int(v):
    return isinstance(v, int) and not isinstance(v, bool)

def finish():
    for good, what, detail in results:
        print(("ok   " if good else "FAIL ") + label + ": " + what
              + ("" if good or not detail else ": " + detail))
    sys.exit(0)

# ---- summary.json ----
try:
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
except Exception as e:  # noqa: BLE001
    check(False, "summary.json is valid JSON", str(e))
    finish()
check(isinstance(s, dict), "summary.json is one object")
top = {"model": str, "duration_s": "num", "time_step_s": "num", "steps": "int",
       "nodes": "int", "belt_length_m": "num", "wall_time_s": "num",
       "tension": dict, "probes": dict, "pulleys": dict, "energy": dict,
       "warnings": list}

def typed(v, t):
    if t == "num":
        return is_num(v)
    if t == "int":
        return is_int(v)
    return isinstance(v, t)

bad_keys = [k for k, t in top.items() if k not in s or not typed(s[k], t)]
if not check(not bad_keys, "summary.json has every top-level key with its type",
             "missing or mistyped: %s" % bad_keys):
    finish()
check(s["model"] == exp["model"], "model is the name from the file",
      "%r, want %r" % (s["model"], exp["model"]))
dt = s["time_step_s"]
check(dt > 0 and s["steps"] > 0 and s["nodes"] > 0 and s["belt_length_m"] > 0
      and s["wall_time_s"] >= 0, "time step, steps, nodes, belt length positive")
check(abs(s["duration_s"] - exp["duration"]) <= dt,
      "duration_s within one step of the model's duration",
      "%g vs %g (step %g)" % (s["duration_s"], exp["duration"], dt))
check(abs(s["steps"] * dt - s["duration_s"]) <= dt,
      "steps x time_step_s = duration_s", "%d x %g vs %g" % (s["steps"], dt, s["duration_s"]))
tk = ["max_N", "max_time_s", "max_s_m", "min_N", "min_time_s", "min_s_m"]
t = s["tension"]
if check(all(k in t and is_num(t[k]) for k in tk), "tension has %s as numbers" % tk,
         str(t)):
    check(t["min_N"] <= t["max_N"], "tension min_N <= max_N")
    for k in ("max", "min"):
        check(0 <= t[k + "_time_s"] <= s["duration_s"] + dt
              and 0 <= t[k + "_s_m"] <= s["belt_length_m"],
              "tension %s within the run and the belt" % k, str(t))
check(list(s["probes"]) == exp["probes"], "probes lists every probe of the model",
      "%s, want %s" % (list(s["probes"]), exp["probes"]))
pk = ["tension_max_N", "tension_min_N", "tension_final_N", "speed_final_mps"]
for name, p in s["probes"].items():
    if check(isinstance(p, dict) and all(k in p and is_num(p[k]) for k in pk),
             "probe %s has %s as numbers" % (name, pk), str(p)):
        check(p["tension_min_N"] <= p["tension_final_N"] <= p["tension_max_N"],
              "probe %s: min <= final <= max tension" % name, str(p))
check(sorted(s["pulleys"]) == sorted(exp["pulleys"]), "pulleys lists every pulley",
      "%s, want %s" % (list(s["pulleys"]), exp["pulleys"]))
for name, p in s["pulleys"].items():
    want = ["omega_final_rad_s"]
    if name in exp["drives"]:
        want.append("torque_max_Nm")
    if name in exp["takeups"]:
        want += ["travel_min_m", "travel_max_m"]
    check(isinstance(p, dict) and all(k in p and is_num(p[k]) for k in want),
          "pulley %s has %s as numbers" % (name, want), str(p))
    if name not in exp["drives"]:
        check("torque_max_Nm" not in p, "pulley %s (no drive) has no torque_max_Nm" % name)
    if name not in exp["takeups"]:
        check("travel_min_m" not in p and "travel_max_m" not in p,
              "pulley %s (no takeup) has no travel_*" % name)
    else:
        check(p.get("travel_min_m", 1) <= 0 <= p.get("travel_max_m", -1),
              "pulley %s: travel_min_m <= 0 <= travel_max_m (travel from the initial position)"
              % name, str(p))
e = s["energy"]
check(all(k in e and is_num(e[k]) for k in ("kinetic_final_J", "balance_error_rel"))
      and e["kinetic_final_J"] >= 0 and e["balance_error_rel"] >= 0,
      "energy has kinetic_final_J and balance_error_rel, both >= 0", str(e))
check(all(isinstance(w, str) for w in s["warnings"]), "warnings is a list of strings")

# ---- history.csv ----
def read_csv(name):
    with open(os.path.join(out, name), newline="") as f:
        return list(csv.reader(f))

hist = read_csv("history.csv")
want = ["t_s"]
for p in exp["probes"]:
    want += [p + ".tension_N", p + ".speed_mps"]
for d in exp["drives"]:
    want += [d + ".omega_rad_s", d + ".torque_Nm"]
for k in exp["takeups"]:
    want += [k + ".travel_m"]
want += ["kinetic_J", "potential_J", "dissipated_J", "input_J"]
check(hist and hist[0] == want, "history.csv header",
      "%s, want %s" % (hist[0] if hist else None, want))
rows = hist[1:]
check(rows and all(len(r) == len(want) for r in rows),
      "history.csv rows have %d columns" % len(want))
try:
    times = [float(r[0]) for r in rows]
    values = [float(x) for r in rows for x in r]
    check(all(math.isfinite(v) for v in values), "history.csv values are finite numbers")
except ValueError as ex:
    check(False, "history.csv values are numbers", str(ex))
    times = []
if times:
    iv = exp["interval"]
    check(times[0] == 0.0, "history.csv first row at t = 0", str(times[0]))
    gaps = [b - a for a, b in zip(times, times[1:])]
    worst = max(abs(g - iv) for g in gaps) if gaps else float("inf")
    check(worst <= dt + 1e-6, "history.csv rows every output_interval %g within one step" % iv,
          "worst spacing error %g s (step %g)" % (worst, dt))
    check(abs(times[-1] - exp["duration"]) <= dt + 1e-6,
          "history.csv last row at the duration within one step",
          "%g vs %g" % (times[-1], exp["duration"]))
    n_want = round(exp["duration"] / iv) + 1
    check(abs(len(times) - n_want) <= 1, "history.csv has duration/interval + 1 rows",
          "%d rows, want %d" % (len(times), n_want))

# ---- tension.csv ----
ten = read_csv("tension.csv")
hdr = ["t_s", "s_m", "x_m", "y_m", "tension_N", "speed_mps"]
check(ten and ten[0] == hdr, "tension.csv header", str(ten[0] if ten else None))
groups = []   # [t, count]
bad_row = None
for r in ten[1:]:
    if len(r) != len(hdr):
        bad_row = r
        break
    try:
        vals = [float(x) for x in r]
    except ValueError:
        bad_row = r
        break
    # s_m is printed to 0.1 mm: allow that rounding at the ends
    if not (-1e-4 <= vals[1] <= s["belt_length_m"] + 1e-4):
        bad_row = r
        break
    if groups and groups[-1][0] == r[0]:
        groups[-1][1] += 1
    else:
        groups.append([r[0], 1])
check(bad_row is None, "tension.csv rows: 6 numbers, s_m in [0, belt_length_m]", str(bad_row))
check(groups and all(c == s["nodes"] for _, c in groups),
      "tension.csv has one row per node (%d) at every output time" % s["nodes"],
      "counts %s" % sorted({c for _, c in groups}))
if times:
    gt = [float(g[0]) for g in groups]
    check(len(gt) == len(times) and all(abs(a - b) <= 1e-6 for a, b in zip(gt, times)),
          "tension.csv output times are history.csv's times",
          "%d vs %d times" % (len(gt), len(times)))

# ---- envelope.csv ----
env = read_csv("envelope.csv")
check(env and env[0] == ["s_m", "tension_max_N", "tension_min_N"], "envelope.csv header",
      str(env[0] if env else None))
try:
    ev = [[float(x) for x in r] for r in env[1:]]
    check(ev and all(len(r) == 3 for r in ev), "envelope.csv rows have 3 numbers")
    ss = [r[0] for r in ev]
    check(all(b > a for a, b in zip(ss, ss[1:])), "envelope.csv s_m strictly increasing")
    check(ss and ss[0] >= 0 and ss[-1] <= s["belt_length_m"],
          "envelope.csv s_m within [0, belt_length_m]",
          "%g..%g, L = %g" % (ss[0], ss[-1], s["belt_length_m"]) if ss else "")
    check(all(r[2] <= r[1] for r in ev), "envelope.csv tension_min_N <= tension_max_N")
    if "max_N" in t:
        # both are over the whole run: the envelope cannot exceed the
        # summary's extremes (nor can tension.csv, whose rows it is made of).
        # envelope.csv prints 6 significant digits (%.6g) and rounding to
        # them keeps order, so it is compared with the summary's values
        # printed the same way, exactly (185104.72 N prints 185105 in both)
        emax, emin = max(r[1] for r in ev), min(r[2] for r in ev)
        check(emax <= float("%.6g" % t["max_N"]) and emin >= float("%.6g" % t["min_N"]),
              "envelope.csv within summary tension min_N..max_N",
              "envelope %g..%g N, summary %g..%g N" % (emin, emax, t["min_N"], t["max_N"]))
except ValueError as ex:
    check(False, "envelope.csv values are numbers", str(ex))
finish()
PY

# run_case LABEL MODEL EXPECTATIONS_JSON
run_case() {
    local label=$1 model=$2 exp=$3 dir="$tmp/$1"
    "$BELTDYN" run "$model" -o "$dir" >"$tmp/$label.out" 2>"$tmp/$label.err"
    local rc=$?
    if [ $rc -ne 0 ]; then bad "$label" "run exit $rc: $(cat "$tmp/$label.err")"; return; fi
    ok "$label: run exits 0"
    if [ -s "$tmp/$label.err" ]; then
        bad "$label" "stderr is not empty with stderr not a terminal: $(head -c 300 "$tmp/$label.err")"
    else
        ok "$label: no progress line (stderr empty, not a terminal)"
    fi
    local left
    left=$(find "$dir" -mindepth 1 \( -name '*.part*' -o -name '.*' -o -name '*.tmp' \) | head -5)
    if [ -z "$left" ]; then ok "$label: no temporary files left"
    else bad "$label" "temporary files left: $left"; fi
    for f in summary.json history.csv tension.csv envelope.csv; do
        [ -s "$dir/$f" ] || bad "$label" "$f missing or empty"
    done
    local line
    while IFS= read -r line; do
        case "$line" in
        "ok   "*) echo "$line"; passed=$((passed + 1)) ;;
        *) echo "$line"; failed=$((failed + 1)) ;;
        esac
    done < <(python3 "$tmp/check.py" "$dir" "$exp" 2>&1 || echo "FAIL $label: checker crashed")
}

# the expectations below are those of the example files: guard against drift
expect_in() { # file regex
    grep -qE "$2" "$1" || bad "$(basename "$1")" "expected /$2/ in the model file (update this test)"
}
flat="$EXAMPLES/flat_belt_drive.yaml"
expect_in "$flat" '^name: two-pulley flat belt drive$'
expect_in "$flat" '^  duration: 1\.5$'
expect_in "$flat" '^  output_interval: 0\.002$'
run_case flat "$flat" '{"label": "flat", "model": "two-pulley flat belt drive",
  "duration": 1.5, "interval": 0.002, "probes": ["tight", "slack"],
  "pulleys": ["motor", "driven"], "drives": ["motor"], "takeups": []}'

vert="$EXAMPLES/vertical_loop.yaml"
expect_in "$vert" '^name: vertical two-pulley loop \(seed 001 ch\. 6\)$'
expect_in "$vert" '^  duration: 5$'
expect_in "$vert" '^  output_interval: 0\.01$'
run_case vertical "$vert" '{"label": "vertical", "model": "vertical two-pulley loop (seed 001 ch. 6)",
  "duration": 5, "interval": 0.01, "probes": ["down_mid", "up_mid", "down_low"],
  "pulleys": ["top", "takeup"], "drives": [], "takeups": ["takeup"]}'

# --quiet is accepted (and prints nothing on stderr either)
"$BELTDYN" run "$flat" -o "$tmp/quiet" --quiet >/dev/null 2>"$tmp/quiet.err"
rc=$?
if [ $rc -eq 0 ] && [ ! -s "$tmp/quiet.err" ] && [ -s "$tmp/quiet/summary.json" ]; then
    ok "--quiet accepted"
else
    bad "--quiet" "exit $rc, stderr: $(head -c 300 "$tmp/quiet.err")"
fi

# on a terminal (util-linux `script` gives the run a pty) a progress line
# with simulated time, percent, wall time, remaining time and real-time factor
# appears; --quiet silences it
if command -v script >/dev/null 2>&1; then
    tty_out=$(script -qec "'$BELTDYN' run '$flat' -o '$tmp/tty'" /dev/null 2>&1 | tr '\r' '\n')
    if printf '%s\n' "$tty_out" | grep -qE 't = +[0-9.]+ s +[0-9.]+% +wall .*remaining .*real time'; then
        ok "progress line on a terminal"
    else
        bad "progress line on a terminal" "none seen: $(printf '%s' "$tty_out" | head -c 300)"
    fi
    tty_out=$(script -qec "'$BELTDYN' run '$flat' -o '$tmp/tty_quiet' --quiet" /dev/null 2>&1)
    if [ -z "$tty_out" ] && [ -s "$tmp/tty_quiet/summary.json" ]; then ok "--quiet silences the progress line on a terminal"
    else bad "--quiet on a terminal" "printed: $(printf '%s' "$tty_out" | head -c 300)"; fi
else
    echo "skip progress line on a terminal: no 'script' command"
fi

# without -o the outputs go to ./out
mkdir -p "$tmp/cwd"
(cd "$tmp/cwd" && "$BELTDYN" run "$flat" --quiet >/dev/null 2>&1)
rc=$?
if [ $rc -eq 0 ] && [ -s "$tmp/cwd/out/summary.json" ] && [ -s "$tmp/cwd/out/history.csv" ]; then
    ok "default DIR is ./out"
else
    bad "default DIR" "exit $rc; $(ls "$tmp/cwd" 2>&1)"
fi

tally
