# Sourced by the command's tests: count checks, say each, end with the tally.
passed=0
failed=0
ok() { echo "ok   $1"; passed=$((passed + 1)); }
bad() { echo "FAIL $1: $2"; failed=$((failed + 1)); }
# a check whose verdict is a line: "ok ..." passes (said with it), anything
# else fails with the line as the reason
judge() {
    case "$2" in
        ok*) ok "$1: ${2:0:200}" ;;
        *) bad "$1" "$2" ;;
    esac
}
# the last command of a test: its summary line and its exit status
tally() {
    echo "$passed passed, $failed failed"
    [ $failed -eq 0 ]
}
