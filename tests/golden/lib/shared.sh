# Sourced by golden tests that read ../shared (the validation scenes and RADIANCE's test
# models, which are not in the repository): in a clone without it, require_shared skips
# the test with one line (ctest's skip code 77, tests/CMakeLists.txt).
require_shared() {
    local path="${RP_SHARED_DIR:-}/$1"
    if [ -z "${RP_SHARED_DIR:-}" ] || [ ! -e "$path" ]; then
        echo "skipped: $path missing (no ../shared)"
        exit 77
    fi
}
