#!/usr/bin/env bash
# A whole chapter through the Slurm executor (ctest cluster.chapter-ch3, label
# full) or a command template: the chapter's quick tier runs again with
# --executor slurm on a single-node Slurm started here (local_slurm.sh), or
# with --executor 'command:...' (a shell running `drawbend run` on one
# thread), and its checks.csv, values.csv and every file of tables/ (tables,
# field files) must equal the local run's byte for byte, less the
# configuration lines that name the output folder and the executor, and the
# values that are wall times (*_wall: db_wall, chapter_wall, runs_wall; a
# table's *wall_s column).
# Exit 77 (skipped) when Slurm cannot be started (not root, no packages).
#   chapter_check.sh CHAPTER_EXE DRAWBEND LOCAL_OUT OUT [slurm|command] [CHAPTER_ARGS...]
# CHAPTER_ARGS (for example --tier full --full-study true) go to the chapter
# as given; the local run in LOCAL_OUT must have had the same ones.
set -u
exe=$1 drawbend=$2 local_out=$3 out=$4 executor=${5:-slurm}
shift $(( $# < 5 ? $# : 5 ))
here=$(cd "$(dirname "$0")" && pwd)
fail() { echo "FAIL: $*"; exit 1; }
[ -s "$local_out/checks.csv" ] || fail "no local run of the chapter in $local_out"
case $executor in
  slurm)
    source "$here/local_slurm.sh"
    trap slurm_stop EXIT
    slurm_start "$out.slurm_state"; rc=$?
    [ $rc -eq 77 ] && exit 77
    [ $rc -eq 0 ] || fail "could not start the local Slurm" ;;
  command) executor='command:{drawbend} run {deck} --out {dir} {args} --quiet --threads {cores} > {dir}/run.log' ;;
  *) fail "executor: expected slurm or command, found '$executor'" ;;
esac
rm -rf "$out"
t0=$(date +%s)
DRAWBEND_BIN=$drawbend OMP_WAIT_POLICY=PASSIVE "$exe" --out "$out" --executor "$executor" "$@" > "$out.log" 2>&1 ||
  { tail -30 "$out.log"; fail "the chapter through ${executor%%:*}"; }
# A CSV less what names the run's folder or executor and the wall times: rows
# named *wall and, in a table, the values of a column named *wall_s (the
# full tier's mass-scaling and width tables; such tables quote no commas).
comparable() {
  grep -a -v -e '^#   out = ' -e '^#   executor = ' -e '^[a-z_]*wall,' "$1" |
    awk -F, 'BEGIN { OFS = "," } /^#/ { print; next }
             !h { for (i = 1; i <= NF; i++) if ($i ~ /wall_s$/) w[i] = 1; h = 1; print; next }
             { for (i in w) $i = ""; print }'
}
n=0
for f in "$local_out"/checks.csv "$local_out"/values.csv "$local_out"/tables/*; do
  g=$out/${f#"$local_out"/}
  case $f in
    *.csv) diff <(comparable "$f") <(comparable "$g") > /dev/null ;;
    *) cmp -s "$f" "$g" ;;  # field files and the like: whole
  esac || fail "${f#"$local_out"/} differs between the local and the ${executor%%:*} run"
  n=$((n + 1))
done
echo "chapter through ${executor%%:*}: $n files byte-identical to the local run ($(ls -d "$out"/runs/*/ 2>/dev/null | wc -l) run folders, $(( $(date +%s) - t0 )) s)"
