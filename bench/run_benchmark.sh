#!/usr/bin/env bash
# Benchmark apollonius3d against voronota calculate-vertices on the same balls.
# See bench/README.md. Usage: bench/run_benchmark.sh --help
set -euo pipefail

SCRIPT_DIR=$(cd "$(dirname "$0")" && pwd)
REPO_DIR=$(cd "$SCRIPT_DIR/.." && pwd)

# ---- defaults (env vars override, flags override env vars) -----------------
DATA_DIR=${BENCH_DATA_DIR:-"$SCRIPT_DIR/data"}
WORK_DIR=${BENCH_WORK_DIR:-"$SCRIPT_DIR/work"}
APOLLONIUS=${APOLLONIUS3D:-"$REPO_DIR/build/apollonius3d"}
VORONOTA=${VORONOTA:-voronota}
APOLLONIUS_ARGS=${APOLLONIUS_ARGS:-}
INPUTS="BALL_SMALL_1000,BALL_SMALL_2000,BALL_SMALL_5000,BALL_SMALL_10000,1j3h,1hpv"
REPEAT=3
TIMEOUT=600          # seconds per run; 0 = no limit
THREADS_SWEEP=0
SWEEP_THREADS=2
ONLY=both            # both | voronota | apollonius
DIAGRAM=0            # also time 'apollonius3d diagram' (the whole diagram) on each input

usage() {
  cat <<EOF
Usage: $0 [options]
  --inputs LIST           comma-separated inputs (default: $INPUTS)
                          names: BALL_SMALL_N, 1j3h, 1hpv, pept, a path to a balls file, or
                          generate:FAMILY:N:SEED ('apollonius3d generate FAMILY --n N --seed SEED')
  --repeat R              runs per tool and input (default: $REPEAT)
  --apollonius-args "..." extra arguments for 'apollonius3d vertices' (env APOLLONIUS_ARGS)
  --timeout SECONDS       limit per run, 0 = none (default: $TIMEOUT); shown as >T
  --threads-sweep         also run apollonius3d with --threads $SWEEP_THREADS (base runs get --threads 1)
  --only both|voronota|apollonius   run only one tool (default: both)
  --diagram               also run 'apollonius3d diagram' (edges, faces, cells) and report its time,
                          memory and ratio to 'vertices'
  --work-dir DIR          where inputs/outputs go (env BENCH_WORK_DIR, default bench/work)
Env: BENCH_DATA_DIR (default bench/data), APOLLONIUS3D (binary), VORONOTA (binary).
EOF
}

die() { echo "run_benchmark: error: $*" >&2; exit 1; }
log() { echo "run_benchmark: $*" >&2; }

# ---- options ---------------------------------------------------------------
while [[ $# -gt 0 ]]; do
  case $1 in
    --inputs)          INPUTS=$2; shift 2 ;;
    --repeat)          REPEAT=$2; shift 2 ;;
    --apollonius-args) APOLLONIUS_ARGS=$2; shift 2 ;;
    --timeout)         TIMEOUT=$2; shift 2 ;;
    --threads-sweep)   THREADS_SWEEP=1; shift ;;
    --only)            ONLY=$2; shift 2 ;;
    --diagram)         DIAGRAM=1; shift ;;
    --work-dir)        WORK_DIR=$2; shift 2 ;;
    -h|--help)         usage; exit 0 ;;
    *)                 usage >&2; die "unknown option '$1'" ;;
  esac
done
[[ $REPEAT =~ ^[1-9][0-9]*$ ]] || die "--repeat must be a positive integer"
[[ $TIMEOUT =~ ^[0-9]+$ ]] || die "--timeout must be a whole number of seconds"
[[ $ONLY =~ ^(both|voronota|apollonius)$ ]] || die "--only must be both, voronota or apollonius"
run_a() { [[ $ONLY != voronota ]]; }
run_v() { [[ $ONLY != apollonius ]]; }

[[ -x /usr/bin/time ]] || die "GNU time not found at /usr/bin/time"
run_v && { command -v "$VORONOTA" >/dev/null || die "voronota not found ('$VORONOTA')"; }
run_a && { [[ -x $APOLLONIUS ]] || die "apollonius3d not found at '$APOLLONIUS' (run scripts/build.sh)"; }
read -r -a A_ARGS <<<"$APOLLONIUS_ARGS"
mkdir -p "$WORK_DIR/inputs" "$WORK_DIR/out"
RUNLOG="$WORK_DIR/runs.tsv"
printf 'input\ttool\trep\tstatus\twall_s\ttime_e_s\tmaxrss_kib\n' >"$RUNLOG"

# ---- input preparation: every input becomes one 'x y z r' balls file --------
# prepare_input NAME -> prints the path of the balls file (cached in WORK_DIR/inputs)
prepare_input() {
  local name=$1 src out
  case $name in
    */*|*.balls)                      # an explicit balls file, used as it is
      [[ -f $name ]] || die "input file '$name' not found"
      echo "$name"; return ;;
    pept)
      echo "$REPO_DIR/tests/data/pept.balls"; return ;;
    generate:*)                       # generate:FAMILY:N:SEED, made by apollonius3d itself
      local family count seed
      IFS=: read -r _ family count seed <<<"$name"
      [[ -n $family && $count =~ ^[1-9][0-9]*$ && $seed =~ ^[0-9]+$ ]] ||
        die "input '$name' is not generate:FAMILY:N:SEED"
      [[ -x $APOLLONIUS ]] || die "apollonius3d not found at '$APOLLONIUS', needed to generate '$name'"
      out="$WORK_DIR/inputs/generate_${family}_${count}_${seed}.balls"
      if [[ ! -s $out || $APOLLONIUS -nt $out ]]; then
        "$APOLLONIUS" generate "$family" --n "$count" --seed "$seed" -o "$out" ||
          die "apollonius3d could not generate '$name'"
      fi ;;
    BALL_SMALL_*|ANO*|Vis_*|Ext_*)    # vdrc: count line, then 'id x y z r'
      src="$DATA_DIR/vdrc/$name.txt"
      out="$WORK_DIR/inputs/$name.balls"
      [[ -f $src ]] || die "vdrc input '$src' not found (set BENCH_DATA_DIR)"
      if [[ ! -s $out || $src -nt $out ]]; then
        awk 'NR > 1 && NF >= 5 { print $2, $3, $4, $5 }' "$src" >"$out.tmp" && mv "$out.tmp" "$out"
      fi ;;
    *)                                # PDB entry: atoms -> balls with voronota's radii
      src="$DATA_DIR/pdb/$name.pdb"
      out="$WORK_DIR/inputs/$name.balls"
      [[ -f $src ]] || die "PDB input '$src' not found (set BENCH_DATA_DIR)"
      if [[ ! -s $out || $src -nt $out ]]; then
        command -v voronota >/dev/null || die "voronota is needed to convert '$src'"
        voronota get-balls-from-atoms-file <"$src" >"$out.tmp" || die "voronota could not convert '$src'"
        mv "$out.tmp" "$out"
      fi ;;
  esac
  [[ -s $out ]] || die "input '$name' produced an empty balls file"
  echo "$out"
}

# count_sites FILE: non-empty, non-comment lines
count_sites() { awk '{ sub(/#.*/, "") } NF >= 4 { n++ } END { print n + 0 }' "$1"; }
# count_vertices FILE: lines 'q1 q2 q3 q4 [...] x y z r'
count_vertices() { awk '!/^#/ && NF >= 8 { n++ } END { print n + 0 }' "$1"; }

# ---- one timed run ---------------------------------------------------------
# timed_run INPUT TOOL REP BALLS OUT CMD... ; the command reads BALLS on stdin
# when its args contain no '{}' (voronota), else '{}' is replaced by BALLS.
# Appends to RUNLOG; sets LAST_STATUS (ok|timeout), LAST_WALL, LAST_RSS.
timed_run() {
  local input=$1 tool=$2 rep=$3 balls=$4 out=$5; shift 5
  local tfile="$WORK_DIR/out/time.txt" efile="$WORK_DIR/out/stderr.txt"
  local -a cmd=() tcmd=()
  local arg stdin=$balls rc=0 t0 t1 line
  for arg in "$@"; do
    if [[ $arg == '{}' ]]; then cmd+=("$balls"); stdin=/dev/null; else cmd+=("$arg"); fi
  done
  (( TIMEOUT > 0 )) && tcmd=(timeout -k 10 "$TIMEOUT")
  : >"$efile"; : >"$tfile"
  t0=$EPOCHREALTIME
  /usr/bin/time -f "%e %M" -o "$tfile" "${tcmd[@]}" "${cmd[@]}" <"$stdin" >"$out" 2>"$efile" || rc=$?
  t1=$EPOCHREALTIME
  line=$(tail -n 1 "$tfile" 2>/dev/null || true)   # time prepends a note on non-zero exit
  LAST_WALL=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.3f", b - a }')
  LAST_RSS=${line#* }
  if (( rc == 124 || rc == 137 )) && (( TIMEOUT > 0 )); then
    LAST_STATUS=timeout
    log "  $tool on $input: timed out after ${TIMEOUT}s (rep $rep)"
  elif (( rc != 0 )); then
    echo "run_benchmark: error: $tool failed on $input (exit $rc): ${cmd[*]}" >&2
    tail -n 20 "$efile" | sed 's/^/  | /' >&2
    exit 1
  else
    LAST_STATUS=ok
  fi
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$input" "$tool" "$rep" "$LAST_STATUS" \
    "$LAST_WALL" "${line%% *}" "$LAST_RSS" >>"$RUNLOG"
}

# ---- statistics over the runs of one tool ----------------------------------
# A tool's runs are an array of wall seconds, with T for a timed-out run.
median() {   # median WORDS... -> seconds with 3 decimals, or >T
  printf '%s\n' "$@" | sed 's/^T$/1e300/' | sort -g | awk -v T="$TIMEOUT" '
    { v[NR] = $1 + 0 }
    END { m = (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
          if (m >= 1e299) printf ">%s", T; else printf "%.3f", m }'
}
mib() { awk -v k="$1" 'BEGIN { if (k == "") print "-"; else printf "%.1f", k / 1024 }'; }
ratio() {    # ratio A V -> A/V, or a bound when one side timed out
  awk -v a="$1" -v v="$2" 'BEGIN {
    if (a == "-" || v == "-" || v ~ />/) { print "n/a"; exit }
    if (a ~ />/) { sub(/>/, "", a); if (v > 0) printf ">%.1f", a / v; else print "n/a"; exit }
    if (v > 0) printf "%.2f", a / v; else print "n/a" }'
}

# ---- benchmark one input: interleaved A, [A2], V runs -----------------------
# Prints one Markdown table row.
bench_input() {
  local name=$1 label balls sites r
  local a_times=() a2_times=() v_times=() d_times=() a_rss=0 v_rss=0 d_rss=0
  label=$(basename "$name" .balls)
  local a_verts=- v_verts=- a_out="$WORK_DIR/out/$label.apollonius.txt" v_out="$WORK_DIR/out/$label.voronota.txt"
  local -a a_base=("$APOLLONIUS" vertices '{}' "${A_ARGS[@]}")
  (( THREADS_SWEEP )) && a_base+=(--threads 1)
  balls=$(prepare_input "$name")
  sites=$(count_sites "$balls")
  log "$label: $sites sites, $REPEAT repetitions"
  for (( r = 1; r <= REPEAT; r++ )); do
    if run_a; then
      timed_run "$label" apollonius3d "$r" "$balls" "$a_out" "${a_base[@]}"
      if [[ $LAST_STATUS == ok ]]; then a_times+=("$LAST_WALL"); a_verts=$(count_vertices "$a_out"); else a_times+=(T); fi
      (( LAST_RSS > a_rss )) 2>/dev/null && a_rss=$LAST_RSS
      if (( DIAGRAM )); then
        timed_run "$label" apollonius3d-diagram "$r" "$balls" "$a_out.diagram.json" \
          "$APOLLONIUS" diagram '{}' "${A_ARGS[@]}" --threads 1
        if [[ $LAST_STATUS == ok ]]; then d_times+=("$LAST_WALL"); else d_times+=(T); fi
        (( LAST_RSS > d_rss )) 2>/dev/null && d_rss=$LAST_RSS
      fi
      if (( THREADS_SWEEP )); then
        timed_run "$label" "apollonius3d-t$SWEEP_THREADS" "$r" "$balls" "$a_out.t$SWEEP_THREADS" \
          "$APOLLONIUS" vertices '{}' "${A_ARGS[@]}" --threads "$SWEEP_THREADS"
        if [[ $LAST_STATUS == ok ]]; then a2_times+=("$LAST_WALL"); else a2_times+=(T); fi
      fi
    fi
    if run_v; then
      timed_run "$label" voronota "$r" "$balls" "$v_out" "$VORONOTA" calculate-vertices
      if [[ $LAST_STATUS == ok ]]; then v_times+=("$LAST_WALL"); v_verts=$(count_vertices "$v_out"); else v_times+=(T); fi
      (( LAST_RSS > v_rss )) 2>/dev/null && v_rss=$LAST_RSS
    fi
  done
  local a_med=- v_med=- a_mib=- v_mib=-
  run_a && { a_med=$(median "${a_times[@]}"); a_mib=$(mib "$a_rss"); }
  run_v && { v_med=$(median "${v_times[@]}"); v_mib=$(mib "$v_rss"); }
  local row="| $label | $sites | $a_med | $v_med | $(ratio "$a_med" "$v_med") | $a_mib | $v_mib | $a_verts | $v_verts |"
  if (( THREADS_SWEEP )); then
    local a2_med=- speedup=n/a
    run_a && a2_med=$(median "${a2_times[@]}")
    [[ $a_med != - && $a2_med != - && $a_med != \>* && $a2_med != \>* ]] &&
      speedup=$(awk -v a="$a_med" -v b="$a2_med" 'BEGIN { if (b > 0) printf "%.2f", a / b; else print "n/a" }')
    row+=" $a2_med | $speedup |"
  fi
  if (( DIAGRAM )); then
    local d_med
    d_med=$(median "${d_times[@]}")
    row+=" $d_med | $(mib "$d_rss") | $(ratio "$d_med" "$a_med") |"
  fi
  echo "$row"
}

# ---- main ------------------------------------------------------------------
cpu=$(awk -F': *' '/^model name/ { print $2; exit }' /proc/cpuinfo 2>/dev/null || true)
commit=$(git -C "$REPO_DIR" rev-parse --short HEAD 2>/dev/null || echo unknown)
vversion=$("$VORONOTA" --version 2>/dev/null | head -n 1 || true)
echo "Machine: $(nproc) CPUs, ${cpu:-unknown CPU}; date: $(date '+%Y-%m-%d %H:%M %Z')"
echo "apollonius3d: commit $commit, args: '${APOLLONIUS_ARGS}'$( (( THREADS_SWEEP )) && echo ' --threads 1'); voronota: ${vversion:-$(dpkg-query -W -f '${Version}' voronota 2>/dev/null || echo unknown)}"
echo "Repetitions: $REPEAT per tool (interleaved), timeout: $( (( TIMEOUT > 0 )) && echo "${TIMEOUT}s" || echo none). Times are medians in seconds."
echo
header="| input | sites | apollonius3d s | voronota s | ratio A/V | apollonius3d MiB | voronota MiB | apollonius3d vertices | voronota vertices |"
sep="|---|--:|--:|--:|--:|--:|--:|--:|--:|"
if (( THREADS_SWEEP )); then
  header+=" apollonius3d ${SWEEP_THREADS} thr s | speed-up 1→${SWEEP_THREADS} |"
  sep+="--:|--:|"
fi
if (( DIAGRAM )); then
  header+=" diagram s | diagram MiB | diagram/vertices |"
  sep+="--:|--:|--:|"
fi
echo "$header"
echo "$sep"
IFS=, read -r -a names <<<"$INPUTS"
for name in "${names[@]}"; do
  [[ -n $name ]] && bench_input "$name"
done
log "per-run log: $RUNLOG"
