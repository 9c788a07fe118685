# Sourced by firmware/run.sh and web/test/run.sh: checks that the pages quote
# the figures a run measured, as the run measured them. Each figure missing is
# counted in $stale and named; quoted_verdict then says whether that fails.

stale=0

# quotes_rows PAGE ROWS: every line of ROWS (a table's rows) is a whole line
# of PAGE.
quotes_rows() {
  local page="$1" row
  while IFS= read -r row; do
    grep -Fxq -- "$row" "$page" || { stale=$((stale + 1)); echo "$page lacks this measured row: $row"; }
  done <<<"$2"
}

# quotes PAGE FIGURE...: PAGE contains each FIGURE.
quotes() {
  local page="$1" figure
  shift
  for figure in "$@"; do
    grep -Fq -- "$figure" "$page" || { stale=$((stale + 1)); echo "$page lacks this measured figure: $figure"; }
  done
}

# quoted_verdict ENFORCE: succeeds when every figure was found, or, with
# ENFORCE other than 1, after saying how many were not.
quoted_verdict() {
  if [ "$stale" = 0 ]; then
    echo "the pages quote the measured figures"
  elif [ "$1" = 1 ]; then
    return 1
  else
    echo "the pages quote other figures than these measurements in $stale place(s) (reported, not failed)"
  fi
}
