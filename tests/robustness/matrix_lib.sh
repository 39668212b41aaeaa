# Sourced by the robustness matrices (hostile_matrix.sh, nonsense_matrix.sh,
# option_lists.sh, newer_commands.sh): one case = one command run under a time
# limit ($limit s) and a 2 GB address-space cap, one table row, and with
# $check set a FAILED line unless the exit code and a message line match.
# The caller sets drawbend, work, check, limit and failed=0 before the cases.

# A 2 GB address-space cap on each run (a bad value must not eat the machine);
# not under AddressSanitizer (tests/sanitize/run.sh sets ASAN_OPTIONS), which
# reserves terabytes of address space for its shadow memory and aborts under it.
cap_memory() { [ -n "${ASAN_OPTIONS:-}" ] || ulimit -v 2000000; }

# expect LABEL CLASS RC PATTERN CMD...: the exit code must be RC and PATTERN
# (grep -E) must match a line of the output (the table shows the first line
# that starts with input error / error / warning / numerical fault).
expect() {
  local label=$1 class=$2 want=$3 pattern=$4
  shift 4
  local out rc first
  out=$( (cap_memory; timeout -k 5 "$limit" "$@") 2>&1 </dev/null)
  rc=$?
  first=$(printf '%s\n' "$out" | grep -a -m1 -E '^(input error|numerical fault|error|data problem|warning)' | cut -c1-300)
  [ -z "$first" ] && first=$(printf '%s\n' "$out" | grep -a -m1 . | cut -c1-300)
  printf '| %s | %s | %s | %s |\n' "$label" "$class" "$rc" "${first//|/\\|}"
  if [ -n "$check" ]; then
    if [ "$rc" != "$want" ] || ! printf '%s\n' "$out" | grep -a -qE -- "$pattern"; then
      echo "FAILED: $label ($class): exit $rc, expected $want and a message matching: $pattern"
      failed=1
    fi
  fi
}
