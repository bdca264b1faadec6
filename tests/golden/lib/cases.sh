# Helpers for golden tests that replay RADIANCE's outputs (sourced; the caller has cd'd
# into its data folder and set RP_BIN, tmp and fail=0).

# Runs every line of cases.txt (tool, then arguments as a shell reads them): its standard
# output must be byte-identical to expected/NN.out. At least $1 cases must be read.
run_cases() {
    local n=0 line tool rest want
    while IFS= read -r line; do
        n=$((n + 1))
        tool=${line%% *}
        [ "$tool" = "$line" ] && rest="" || rest=${line#* }
        want="expected/$(printf %02d $n).out"
        if ! eval "\"\$RP_BIN/$tool\" $rest" > "$tmp/out" 2> "$tmp/err"; then
            echo "FAIL line $n ($line): exit status $?"; cat "$tmp/err"; fail=1; continue
        fi
        if ! cmp -s "$want" "$tmp/out"; then
            echo "FAIL line $n ($line): output differs from $want"
            diff <(od -c "$want" | head -20) <(od -c "$tmp/out" | head -20) | head -10
            fail=1
        fi
    done < cases.txt
    [ "$n" -ge "$1" ] || { echo "FAIL: only $n cases read"; fail=1; }
}

# expect_error PATTERN TOOL ARGS...: the tool fails with one line on stderr matching
# PATTERN; standard input from $IN (default /dev/null).
expect_error() {
    local pattern=$1; shift
    local tool=$1; shift
    if "$RP_BIN/$tool" "$@" > "$tmp/out" 2> "$tmp/err" < "${IN:-/dev/null}"; then
        echo "FAIL: $tool $* should fail"; fail=1; return
    fi
    if [ "$(wc -l < "$tmp/err")" -ne 1 ] || ! grep -q "$pattern" "$tmp/err"; then
        echo "FAIL: $tool $*: stderr '$(cat "$tmp/err")', expected /$pattern/"; fail=1
    fi
}
