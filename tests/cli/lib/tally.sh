# Sourced by the command's tests: count checks, say each, end with the tally.
passed=0
failed=0
ok() { echo "ok   $1"; passed=$((passed + 1)); }
bad() { echo "FAIL $1: $2"; failed=$((failed + 1)); }
# the last command of a test: its summary line and its exit status
tally() {
    echo "$passed passed, $failed failed"
    [ $failed -eq 0 ]
}
