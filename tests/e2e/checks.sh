# Sourced by the end-to-end check scripts: a fresh, empty work folder to run in, and fail(), which
# reports a failed check and counts it; the script ends with `exit $((failures > 0))` or its own report.
#   source checks.sh WORK
work=$1
rm -rf "$work"
mkdir -p "$work"
cd "$work" || exit 1
failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}
