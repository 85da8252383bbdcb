#!/usr/bin/env bash
# The tension field's own interval and spacing (model-format.md
# `simulation.tension_interval`, `tension_spacing`): tension.csv thins in
# time and along the belt while history.csv and envelope.csv stay as they
# are without the keys (same bytes), and an interval below output_interval
# is refused at its line and column.
. "$(dirname "$0")/lib/setup.sh"

model="$tmp/head_drive.yaml"
# 2 s of examples/head_drive.yaml, history every 0.02 s
sed -e 's/^  duration: 12$/  duration: 2/' "$EXAMPLES/head_drive.yaml" >"$tmp/plain.yaml"
sed -e 's/^  output_interval: 0.02$/  output_interval: 0.02\n  tension_interval: 0.1\n  tension_spacing: 2/' \
    "$tmp/plain.yaml" >"$model"
grep -q "tension_spacing: 2" "$model" || bad "test model" "sed did not add the keys"

"$BELTDYN" run "$tmp/plain.yaml" -o "$tmp/plain" --quiet >/dev/null 2>&1 || bad "plain run" "failed"
"$BELTDYN" run "$model" -o "$tmp/thin" --quiet >/dev/null 2>&1 || bad "thinned run" "failed"
# an interval that is no multiple of output_interval: 0.05 s on 0.02 s rows
sed -e 's/^  output_interval: 0.02$/  output_interval: 0.02\n  tension_interval: 0.05/' \
    "$tmp/plain.yaml" >"$tmp/odd.yaml"
"$BELTDYN" run "$tmp/odd.yaml" -o "$tmp/odd" --quiet >/dev/null 2>&1 || bad "odd-interval run" "failed"

# history and envelope are the same bytes: the keys thin the field only
for f in history.csv envelope.csv; do
    if cmp -s "$tmp/plain/$f" "$tmp/thin/$f"; then ok "$f unchanged by the keys"
    else bad "$f unchanged by the keys" "files differ"; fi
done

python3 - "$tmp/plain" "$tmp/thin" "$tmp/odd" >"$tmp/verdicts" 2>&1 <<'PY' || bad "field checker" "crashed: $(cat "$tmp/verdicts")"

import csv, json, sys
from collections import OrderedDict

def field(d):
    rows = OrderedDict()
    with open(d + "/tension.csv") as f:
        r = csv.reader(f)
        next(r)
        for row in r:
            rows.setdefault(row[0], []).append(row)
    return rows

plain, thin = field(sys.argv[1]), field(sys.argv[2])
nodes = json.load(open(sys.argv[2] + "/summary.json"))["nodes"]
L = json.load(open(sys.argv[2] + "/summary.json"))["belt_length_m"]
times = [float(t) for t in thin]
hist = [float(t) for t in plain]
def say(cond, what, detail):
    print(("ok " if cond else "bad ") + what + ("" if cond else " | " + detail))
# every 0.1 s from 0 to 2 s: 21 times, each one of history's times
say(len(times) == 21, "tension.csv at 21 times (0, 0.1, ..., 2 s)", "%d times" % len(times))
say(all(t in plain for t in thin), "its times are history rows' times", str(times[:5]))
# each time within half a history interval of a multiple of 0.1 s
worst = max(abs(t - round(t / 0.1) * 0.1) for t in times)
say(worst <= 0.01, "times within half a history interval of k*0.1 s", "off by %g" % worst)
# along the belt: every k-th element, k = round(2 m / mean element)
k = max(1, round(2.0 / (L / nodes)))
per = [len(v) for v in thin.values()]
want = -(-nodes // k)
say(all(n == want for n in per), "%d points per time (every %d-th of %d elements)" % (want, k, nodes),
    str(sorted(set(per))))
# the thinned rows are the plain field's every k-th row at the same time,
# whole (position, tension, speed): the two runs are the same simulation
diff = [t for t in thin if thin[t] != plain[t][::k]]
say(not diff, "the rows kept are the full field's every k-th row, whole", "differ at %s" % diff[:3])
t0 = next(iter(thin))
s0 = [float(r[1]) for r in thin[t0]]
gaps = [b - a for a, b in zip(s0, s0[1:]) if b > a]
mean_gap = sum(gaps) / len(gaps)
say(abs(mean_gap - 2.0) <= 0.5 * L / nodes + 1e-9, "mean spacing 2 m within half an element",
    "%.4f m" % mean_gap)
# 0.05 s on 0.02 s rows: the first history row at or after each multiple
# (within half a step, as history's own rows): 0, 0.06, 0.10, 0.16, ...
odd = field(sys.argv[3])
want_t = []
for m in range(0, 41):
    due = [t for t in hist if t >= m * 0.05 - 1e-3]
    if due and (not want_t or due[0] != want_t[-1]):
        want_t.append(due[0])
got_t = [float(t) for t in odd]
say(got_t == want_t, "0.05 s on 0.02 s rows: at the first row at or after each multiple (%d times)"
    % len(want_t), "%s vs %s" % (got_t[:6], want_t[:6]))
say(all(odd[t] == plain[t] for t in odd), "those snapshots equal the full field's", "")
PY
while read -r verdict rest; do
    case "$verdict" in
        ok) ok "$rest" ;;
        *) bad "${rest%% | *}" "${rest#* | }" ;;
    esac
done <"$tmp/verdicts"

# below output_interval: refused at the key, nothing written
sed -e 's/^  output_interval: 0.02$/  output_interval: 0.02\n  tension_interval: 0.01/' \
    "$tmp/plain.yaml" >"$tmp/short.yaml"
line=$(grep -n "tension_interval" "$tmp/short.yaml" | cut -d: -f1)
msg=$("$BELTDYN" run "$tmp/short.yaml" -o "$tmp/short" 2>&1)
rc=$?
if [ $rc -eq 2 ] && echo "$msg" | grep -q "short.yaml:$line:[0-9]*: .*simulation.tension_interval.*at least output_interval"; then
    ok "tension_interval below output_interval refused at $line"
else
    bad "tension_interval below output_interval refused" "rc $rc: $msg"
fi
[ ! -e "$tmp/short/tension.csv" ] && ok "nothing written for it" || bad "nothing written" "tension.csv exists"
tally
