# Compares the figures of two versions of a markdown table file written by
# run.sh (icount.md, stack.md, size-table.md): the committed one, then the
# one just measured. Prints one line per figure that changed:
#
#   GREW    <row> / <column>: <old> -> <new> (<relative change>)
#   SHRANK  <row> / <column>: <old> -> <new> (<relative change>)
#   NEW     <row>          (a row only the new file has)
#   COLUMN  <old header> -> <new header>, or new: <header> (a column
#           renamed or added; its figures are compared by position)
#   GONE    <row>          (a row only the committed file has)
#
#   awk -f compare-figures.awk committed.md measured.md
#
# A row is named by its cells before the first that starts with a number
# (the query and precision, the firmware); its figures are the cells that
# start with a number, each read as its leading number ("+1872 B (1.83 KB)"
# is 1872). The QEMU counts and the sizes are deterministic for one
# compiler, so every change is a change of the code, not noise.

function trim(s) {
  gsub(/^[ \t]+|[ \t]+$/, "", s)
  return s
}

# Splits a table line into cells[1..n]; returns n.
function cells_of(line, cells,    n, i, parts) {
  n = split(line, parts, "|")
  # The leading and the trailing "|" leave empty first and last parts.
  for (i = 2; i < n; i++) cells[i - 1] = trim(parts[i])
  return n - 2
}

function is_figure(cell) {
  return cell ~ /^\+?[0-9]/
}

function figure(cell) {
  sub(/^\+/, "", cell)
  match(cell, /^[0-9]+(\.[0-9]+)?/)
  return substr(cell, 1, RLENGTH) + 0
}

FNR == 1 {
  version++
  table = 0
  previous = ""
}

/^\|/ {
  line = $0
  if (line ~ /^\|[ -:|]+\|$/) {
    # The separator: the line before it was the header (the measured
    # file's headers are read last and kept).
    table++
    ncolumns = cells_of(previous, header)
    for (i = 1; i <= ncolumns; i++) heading[version, table, i] = header[i]
    width_of[version, table] = ncolumns
    tables[version] = table
    previous = line
    next
  }
  previous = line
  if (table == 0) next
  n = cells_of(line, cell)
  name = ""
  for (i = 1; i <= n && !is_figure(cell[i]); i++) name = name (name == "" ? "" : ", ") cell[i]
  # No figure: the header of the next table (read here before its
  # separator line says so), not a row.
  if (i > n) next
  key = table SUBSEP name
  for (i = 1; i <= n; i++) if (is_figure(cell[i])) value[version, key, i] = figure(cell[i])
  rows[version]++
  order[version, rows[version]] = key
  listed[version, key] = 1
  label[key] = name
  table_of[key] = table
  width[key] = n
  next
}

{ previous = "" }

END {
  for (t = 1; t <= tables[2]; t++) {
    for (i = 1; i <= width_of[2, t]; i++) {
      if ((1, t, i) in heading && heading[1, t, i] == heading[2, t, i]) continue
      if ((1, t, i) in heading) print "COLUMN  " heading[1, t, i] " -> " heading[2, t, i]
      else print "COLUMN  new: " heading[2, t, i]
    }
  }
  for (r = 1; r <= rows[2]; r++) {
    key = order[2, r]
    if (!((1, key) in listed)) {
      print "NEW     " label[key]
      continue
    }
    for (i = 1; i <= width[key]; i++) {
      if (!((1, key, i) in value) || !((2, key, i) in value)) continue
      old = value[1, key, i]
      new = value[2, key, i]
      if (new == old) continue
      change = old == 0 ? "" : sprintf(" (%+.1f%%)", 100 * (new - old) / old)
      print (new > old ? "GREW    " : "SHRANK  ") label[key] " / " heading[2, table_of[key], i] ": " old " -> " new change
    }
  }
  for (r = 1; r <= rows[1]; r++) {
    key = order[1, r]
    if (!((2, key) in listed)) print "GONE    " label[key]
  }
}
