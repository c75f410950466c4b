# Helpers shared by the CLI test scripts (sourced, POSIX sh).
#   run CMD              store a shell command line to run
#   expect NAME CODE RE  run it (stdout and stderr together), check the exit
#                        code and that a line of the output matches the
#                        extended regex RE
#   expect_whole ...     the same, RE matched against the whole output (it
#                        may span lines; ^ and $ are its start and end)
#   finish               exit 1 if any expectation failed
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0

expect() { check_output "$1" "$2" "$3" -Eq; }
expect_whole() { check_output "$1" "$2" "$3" -Ezq; }
check_output() {
    name=$1 code=$2 regex=$3 grep_flags=$4
    sh "$tmp/cmd" >"$tmp/out" 2>&1
    got=$?
    if [ "$got" -ne "$code" ] || ! grep "$grep_flags" -- "$regex" "$tmp/out"; then
        echo "FAIL $name: exit $got (want $code), output (want /$regex/):"
        sed 's/^/    /' "$tmp/out" | head -20
        failures=$((failures + 1))
    else
        echo "ok   $name"
    fi
}
run() { printf '%s\n' "$1" >"$tmp/cmd"; }
finish() { [ "$failures" -eq 0 ] || { echo "$failures failed"; exit 1; }; }
