# Sourced by the study tests: same_table DIR_A DIR_B compares two studies'
# tables byte for byte, the wall-clock column aside: study.csv without its
# wall_time_s column, study.json without its wall_time_s values (numbers
# as written, 17 significant digits where needed). Prints what differs.
same_table() { # dir_a dir_b
    python3 - "$1" "$2" <<'PY'
import json, sys
a, b = sys.argv[1], sys.argv[2]
def csv(d):
    rows = [l.rstrip("\n").split(",") for l in open(d + "/study.csv")]
    w = rows[0].index("wall_time_s")
    return [r[:w] + r[w + 1:] for r in rows]
def js(d):
    text = open(d + "/study.json").read()
    # drop the wall-clock values, keep every other byte as written
    out = []
    for line in text.splitlines():
        if '"wall_time_s"' not in line:
            out.append(line)
    return out
ca, cb = csv(a), csv(b)
if ca != cb:
    for i, (x, y) in enumerate(zip(ca, cb)):
        if x != y:
            print("study.csv row %d differs:\n  %s\n  %s" % (i, ",".join(x), ",".join(y)))
            break
    else:
        print("study.csv: %d rows against %d" % (len(ca), len(cb)))
    sys.exit(1)
ja, jb = js(a), js(b)
if ja != jb:
    for x, y in zip(ja, jb):
        if x != y:
            print("study.json differs:\n  %s\n  %s" % (x, y))
            break
    else:
        print("study.json: %d lines against %d" % (len(ja), len(jb)))
    sys.exit(1)
# both hold every case, all completed
cases = json.load(open(a + "/study.json"))["cases"]
if not cases or any(c["status"] != "completed" for c in cases):
    print("not every case completed")
    sys.exit(1)
PY
}
