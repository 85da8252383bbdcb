# Sourced first by the command's tests: the command under test (BELTDYN),
# the examples (EXAMPLES), a scratch directory $tmp removed at exit, and
# the tally (tally.sh).
: "${BELTDYN:?BELTDYN must name the built beltdyn}"
EXAMPLES="${EXAMPLES:-$(cd "$(dirname "$0")/../../examples" && pwd)}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$(dirname "${BASH_SOURCE[0]}")/tally.sh"
