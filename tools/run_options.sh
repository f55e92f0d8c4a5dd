# Sourced by the run scripts (run.sh, examples/triaxial/run_triaxial.sh,
# examples/triaxial/run_comparison.sh): the checks their options share. Bash and awk
# only (no Python, nothing installed yet): a wrong option stops the script at once,
# before any installing, building or running.

MAX_RANKS=4096   # far beyond one machine; Open MPI with --oversubscribe would try to start them all

# ranks_or_exit N: the MPI ranks of --np, an integer from 1 to MAX_RANKS (Open MPI runs on
# every slot for -np 0, and its own refusals of -1 or 1.5 are pages long).
ranks_or_exit() {
  [[ "${1-}" =~ ^[1-9][0-9]{0,8}$ ]] && [ "$1" -le "$MAX_RANKS" ] \
    || { echo "--np needs an integer >= 1 and <= $MAX_RANKS (MPI ranks), not '${1-}'" >&2; exit 2; }
}

# The checks below collect their messages in option_errors (report them all with
# options_or_exit); they return 0 (scripts run with set -e).
option_errors=()
option_error() { option_errors+=("$1"); }

# is_number TEXT: a plain decimal number (no nan, inf, hex or text)
is_number() { [[ "${1-}" =~ ^[-+]?([0-9]+([.][0-9]*)?|[.][0-9]+)([eE][-+]?[0-9]+)?$ ]]; }

# is_integer TEXT: a non-negative integer of at most 10 digits
is_integer() { [[ "${1-}" =~ ^[0-9]{1,10}$ ]]; }

# awk_true EXPR [V]: the awk expression is true; V (a number, checked before) is the
# variable v in it, read as a string (1e999 becomes inf, not an awk syntax error)
awk_true() { awk -v v="${2-0}" "BEGIN { v += 0; exit !($1) }"; }

# check_number OPTION VALUE LOW HIGH WHAT [open|closed [WHY]]: LOW <= VALUE <= HIGH (LOW <
# VALUE with 'open'); WHAT says what the number is and WHY the range, for the message.
check_number() {
  local opt=$1 v=$2 lo=$3 hi=$4 what=$5 open=${6-}
  local range="from $lo to $hi"
  [ "$open" = open ] && range="> $lo and <= $hi"
  local why=${7-}
  why=${why:+ ($why)}
  if ! is_number "$v"; then
    option_error "$opt '$v': not a number; needs $what $range$why"
  elif [ "$open" = open ] && ! awk_true "v > $lo" "$v"; then
    option_error "$opt $v: too small; needs $what $range$why"
  elif [ "$open" != open ] && ! awk_true "v >= $lo" "$v"; then
    option_error "$opt $v: too small; needs $what $range$why"
  elif ! awk_true "v <= $hi" "$v"; then
    option_error "$opt $v: too large; needs $what $range$why"
  fi
}

# check_integer OPTION VALUE LOW HIGH WHAT: an integer LOW <= VALUE <= HIGH
check_integer() {
  local opt=$1 v=$2 lo=$3 hi=$4 what=$5
  if ! is_integer "$v" || [ "$((10#$v))" -lt "$lo" ] || [ "$((10#$v))" -gt "$hi" ]; then
    option_error "$opt '$v': needs $what, an integer from $lo to $hi"
  fi
}

# options_or_exit USAGE_HINT: print every message collected and exit 2, if any
options_or_exit() {
  [ ${#option_errors[@]} -eq 0 ] && return 0
  local e
  for e in "${option_errors[@]}"; do echo "$0: $e" >&2; done
  echo "$0: nothing was run; ${1-see --help}" >&2
  exit 2
}
