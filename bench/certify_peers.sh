#!/usr/bin/env bash
# The peers' record, one Markdown table row per input:
#  --peer voronota (default): `voronota calculate-vertices` on each input, then
#    `apollonius3d certify INPUT VORONOTA_OUTPUT --format voronota --report`;
#  --peer voronota-link: the same with `calculate-vertices --link`, its links judged against the edges of
#    the whole diagram, and the vertex-free cells that no vertex list shows;
#  --peer float: `apollonius3d crosscheck INPUT`, our own octree in plain doubles against the certified one.
# See bench/README.md. Usage: bench/certify_peers.sh --help
set -euo pipefail

SCRIPT_DIR=$(cd "$(dirname "$0")" && pwd)
REPO_DIR=$(cd "$SCRIPT_DIR/.." && pwd)

DATA_DIR=${BENCH_DATA_DIR:-"$SCRIPT_DIR/data"}
WORK_DIR=${BENCH_WORK_DIR:-"$SCRIPT_DIR/work/certify"}
APOLLONIUS=${APOLLONIUS3D:-"$REPO_DIR/build/apollonius3d"}
VORONOTA=${VORONOTA:-voronota}
INPUTS=""            # empty: every vdrc set in DATA_DIR/vdrc
SKIP=""
FAMILIES=all         # generator families (needs `apollonius3d generate`); all, none, or a list
N=100
SEED=1
TIMEOUT=600          # seconds per run of either tool
THREADS=1
PEER=voronota        # voronota | voronota-link | float

usage() {
  cat <<EOF
Usage: $0 [options]
  --inputs LIST     comma-separated vdrc set names or balls files, or 'none' (default: every set
                    in \$BENCH_DATA_DIR/vdrc)
  --skip LIST       vdrc sets left out, e.g. BALL_SMALL_10000 (default: none)
  --families LIST   generator families, 'all' or 'none' (default: $FAMILIES); they need
                    'apollonius3d generate KIND --n N --seed S' (balls text on stdout) and are
                    left out, with a note, when the binary has no generate command
  --n N, --seed S   size and seed of the generated inputs (default: $N, $SEED)
  --timeout SECONDS limit per run of each tool (default: $TIMEOUT)
  --threads N       for apollonius3d certify and crosscheck (default: $THREADS)
  --peer NAME       voronota (certify its output), voronota-link (its output with --link: links and
                    vertex-free cells) or float (crosscheck our float path); default: $PEER
  --work-dir DIR    inputs, outputs, reports (default: bench/work/certify)
Env: BENCH_DATA_DIR (default bench/data), APOLLONIUS3D (binary), VORONOTA (binary).
EOF
}

die() { echo "certify_peers: error: $*" >&2; exit 1; }
log() { echo "certify_peers: $*" >&2; }

while [[ $# -gt 0 ]]; do
  case $1 in
    --inputs)   INPUTS=$2; shift 2 ;;
    --skip)     SKIP=$2; shift 2 ;;
    --families) FAMILIES=$2; shift 2 ;;
    --n)        N=$2; shift 2 ;;
    --seed)     SEED=$2; shift 2 ;;
    --timeout)  TIMEOUT=$2; shift 2 ;;
    --threads)  THREADS=$2; shift 2 ;;
    --peer)     PEER=$2; shift 2 ;;
    --work-dir) WORK_DIR=$2; shift 2 ;;
    -h|--help)  usage; exit 0 ;;
    *)          usage >&2; die "unknown option '$1'" ;;
  esac
done
[[ $TIMEOUT =~ ^[1-9][0-9]*$ ]] || die "--timeout must be a positive number of seconds"
[[ $N =~ ^[1-9][0-9]*$ && $SEED =~ ^[0-9]+$ ]] || die "--n and --seed must be integers"
[[ $PEER == voronota || $PEER == voronota-link || $PEER == float ]] || die "--peer must be voronota, voronota-link or float"
[[ $PEER == float ]] || command -v "$VORONOTA" >/dev/null || die "voronota not found ('$VORONOTA')"
[[ -x $APOLLONIUS ]] || die "apollonius3d not found at '$APOLLONIUS' (run scripts/build.sh)"
mkdir -p "$WORK_DIR/inputs" "$WORK_DIR/out"

# ---- inputs: each becomes a balls file 'x y z r' that both tools read ------------------------------
# vdrc: a count line, then 'id x y z r'; the numbers are copied as text, unchanged.
vdrc_balls() {
  local name=$1 src="$DATA_DIR/vdrc/$1.txt" out="$WORK_DIR/inputs/$1.balls"
  [[ -f $src ]] || die "vdrc input '$src' not found (set BENCH_DATA_DIR)"
  awk 'NR > 1 && NF >= 5 { print $2, $3, $4, $5 }' "$src" >"$out"
  echo "$out"
}

# A generated input, comments and blank lines dropped; fails when there is no generate command.
generated_balls() {
  local family=$1 out="$WORK_DIR/inputs/$1-n$N-s$SEED.balls"
  "$APOLLONIUS" generate "$family" --n "$N" --seed "$SEED" 2>/dev/null |
    awk '{ sub(/#.*/, "") } NF >= 4 { print $1, $2, $3, $4 }' >"$out" || return 1
  [[ -s $out ]] || return 1
  echo "$out"
}

# ---- one input: Voronota, then certify its output ------------------------------------------------
# timed OUT IN COMMAND...: runs COMMAND <IN >OUT 2>OUT.stderr under the timeout; sets STATUS
# (ok | timeout >T | exit N) and SECONDS_TAKEN. A failure of the command is recorded, not fatal.
timed() {
  local out=$1 in=$2 rc=0 t0
  shift 2
  t0=$EPOCHREALTIME
  timeout -k 10 "$TIMEOUT" "$@" <"$in" >"$out" 2>"$out.stderr" || rc=$?
  SECONDS_TAKEN=$(awk -v a="$t0" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.2f", b - a }')
  if (( rc == 124 || rc == 137 )); then STATUS="timeout >${TIMEOUT}s"
  elif (( rc == 0 )); then STATUS=ok
  else STATUS="exit $rc"; fi
}

# count NAME REPORT: the integer after "NAME": in the report's counts line (compact or spaced JSON).
count() { grep -m 1 '"counts"' "$2" | sed -E "s/.*\"$1\": ?([0-9]+).*/\1/"; }

# certify_input LABEL FILE_STEM BALLS: prints the table row of one input.
certify_input() {
  local label=$1 stem=$2 balls=$3 sites v_out report v_status v_seconds c_seconds
  sites=$(awk 'NF >= 4 { n++ } END { print n + 0 }' "$balls")
  v_out="$WORK_DIR/out/$stem.voronota.txt"
  report="$WORK_DIR/out/$stem.report.json"
  log "$label: $sites sites"
  timed "$v_out" "$balls" "$VORONOTA" calculate-vertices
  v_status=$STATUS v_seconds=$SECONDS_TAKEN
  local row_end="| $v_seconds |"
  if [[ $v_status != ok ]]; then
    # A failed or killed Voronota run claims nothing that could be judged fairly.
    echo "| $label | $sites | $v_status | - | - | - | - | - | - | - | - | - $row_end - |"
    return
  fi
  rm -f "$report"
  timed "$WORK_DIR/out/$stem.certify.txt" /dev/null \
    "$APOLLONIUS" certify "$balls" "$v_out" --format voronota --report "$report" --threads "$THREADS"
  c_seconds=$SECONDS_TAKEN
  if [[ ! -s $report ]]; then
    # certify exits 1 on discrepancies and still writes the report; no report means it did not finish.
    echo "| $label | $sites | ok, certify: $STATUS | $(awk 'NF >= 8 { n++ } END { print n + 0 }' "$v_out") | - | - | - | - | - | - | - | - $row_end $c_seconds |"
    tail -n 5 "$WORK_DIR/out/$stem.certify.txt.stderr" | sed 's/^/  | /' >&2
    return
  fi
  echo "| $label | $sites | ok | $(count claims "$report") | $(count confirmed "$report") | $(count missing "$report") |" \
       "$(count not_a_vertex "$report") | $(grep -c '"reason": "hidden_site"' "$report") |" \
       "$(count wrong_root "$report") | $(count coordinates_off "$report") |" \
       "$(count duplicate "$report") | $(count surplus "$report") $row_end $c_seconds |"
}

# link_count NAME REPORT: the integer after "NAME": in the report's link counts; - when there are none
# (an empty claim has no links).
link_count() {
  local value
  value=$(grep -m 1 '^  "links"' "$2" | sed -E 's/.*"links": \{"counts":\{([^}]*)\}.*/\1/' | sed -E "s/.*\"$1\":([0-9]+).*/\1/" || true)
  echo "${value:--}"
}

# links_input LABEL FILE_STEM BALLS: the table row of one input for --peer voronota-link.
links_input() {
  local label=$1 stem=$2 balls=$3 sites v_out report v_seconds free
  sites=$(awk 'NF >= 4 { n++ } END { print n + 0 }' "$balls")
  v_out="$WORK_DIR/out/$stem.voronota-link.txt"
  report="$WORK_DIR/out/$stem.link-report.json"
  log "$label: $sites sites"
  timed "$v_out" "$balls" "$VORONOTA" calculate-vertices --link
  v_seconds=$SECONDS_TAKEN
  if [[ $STATUS != ok ]]; then
    echo "| $label | $sites | $STATUS | - | - | - | - | - | - | - | - | - | $v_seconds | - |"
    return
  fi
  rm -f "$report"
  timed "$WORK_DIR/out/$stem.link-certify.txt" /dev/null \
    "$APOLLONIUS" certify "$balls" "$v_out" --format voronota --report "$report" --threads "$THREADS"
  if [[ ! -s $report ]]; then
    echo "| $label | $sites | ok, certify: $STATUS | - | - | - | - | - | - | - | - | - | $v_seconds | $SECONDS_TAKEN |"
    tail -n 5 "$WORK_DIR/out/$stem.link-certify.txt.stderr" | sed 's/^/  | /' >&2
    return
  fi
  free=$(grep -m 1 '"vertex_free_cells"' "$report" | sed -E 's/.*\[(.*)\].*/\1/' | tr ',' '\n' | grep -c '[0-9]' || true)
  echo "| $label | $sites | ok | $(count claims "$report") | $(count confirmed "$report") | $(count missing "$report") |" \
       "$(link_count links "$report") | $(link_count right "$report") | $(link_count wrong "$report") |" \
       "$(link_count missing "$report") | $(link_count not_judged "$report") | $free | $v_seconds | $SECONDS_TAKEN |"
}

# crosscheck_input LABEL FILE_STEM BALLS: the table row of one input for --peer float.
crosscheck_input() {
  local label=$1 stem=$2 balls=$3 sites out summary
  sites=$(awk 'NF >= 4 { n++ } END { print n + 0 }' "$balls")
  out="$WORK_DIR/out/$stem.crosscheck.txt"
  log "$label: $sites sites"
  timed "$out" /dev/null "$APOLLONIUS" crosscheck "$balls" --threads "$THREADS"
  summary=$(tail -n 1 "$out.stderr")
  if [[ $summary != crosscheck:* ]]; then
    echo "| $label | $sites | crosscheck: $STATUS | - | - | - | - | - | - | $SECONDS_TAKEN |"
    return
  fi
  # "crosscheck: certified C vertices, float F; agreeing A, missing M, spurious S, moved V"
  read -r c f a m s v < <(echo "$summary" | sed -E 's/[^0-9]+/ /g')
  echo "| $label | $sites | ok | $c | $f | $a | $m | $s | $v | $SECONDS_TAKEN |"
}

# ---- main ------------------------------------------------------------------------------------------
cpu=$(awk -F': *' '/^model name/ { print $2; exit }' /proc/cpuinfo 2>/dev/null || true)
commit=$(git -C "$REPO_DIR" rev-parse --short HEAD 2>/dev/null || echo unknown)
echo "Machine: $(nproc) CPUs, ${cpu:-unknown CPU}; date: $(date '+%Y-%m-%d %H:%M %Z')"
if [[ $PEER == voronota ]]; then
  echo "apollonius3d: commit $commit, certify --threads $THREADS; voronota: $(dpkg-query -W -f '${Version}' voronota 2>/dev/null || echo unknown); timeout ${TIMEOUT}s per run"
  echo
  echo "| input | sites | voronota | claimed | confirmed | missing | spurious (not a vertex) | of which name a hidden ball | wrong root | coordinates off | duplicate | degenerate surplus | voronota s | certify s |"
  echo "|---|--:|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|"
  check_input=certify_input
elif [[ $PEER == voronota-link ]]; then
  echo "apollonius3d: commit $commit, certify --threads $THREADS; voronota: $(dpkg-query -W -f '${Version}' voronota 2>/dev/null || echo unknown) --link; timeout ${TIMEOUT}s per run"
  echo
  echo "| input | sites | voronota | claimed | confirmed | missing vertices | links | right | wrong | missing links | not judged | vertex-free cells | voronota s | certify s |"
  echo "|---|--:|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|"
  check_input=links_input
else
  echo "apollonius3d: commit $commit, crosscheck --threads $THREADS; timeout ${TIMEOUT}s per run"
  echo
  echo "| input | sites | crosscheck | certified vertices | float vertices | agreeing | missing | spurious | moved | seconds (both paths) |"
  echo "|---|--:|---|--:|--:|--:|--:|--:|--:|--:|"
  check_input=crosscheck_input
fi

if [[ $INPUTS == none ]]; then
  INPUTS=""
elif [[ -z $INPUTS ]]; then
  INPUTS=$(find "$DATA_DIR/vdrc" -maxdepth 1 -name '*.txt' -printf '%f\n' 2>/dev/null | sed 's/\.txt$//' | sort | paste -sd, -)
  [[ -n $INPUTS ]] || die "no vdrc sets in '$DATA_DIR/vdrc' (set BENCH_DATA_DIR)"
fi
IFS=, read -r -a names <<<"$INPUTS"
IFS=, read -r -a skipped <<<"$SKIP"
for name in "${names[@]}"; do
  [[ -n $name ]] || continue
  for s in "${skipped[@]}"; do [[ $name == "$s" ]] && { log "$name: skipped (--skip)"; continue 2; }; done
  if [[ -f $name ]]; then
    $check_input "$(basename "$name" .balls)" "$(basename "$name" .balls)" "$name"
  else
    balls=$(vdrc_balls "$name") || exit 1
    $check_input "$name" "$name" "$balls"
  fi
done

if [[ $FAMILIES != none ]]; then
  if ! "$APOLLONIUS" generate uniform --n 5 --seed 1 >/dev/null 2>&1; then
    log "generator families left out: '$APOLLONIUS' has no generate command"
  else
    if [[ $FAMILIES == all ]]; then  # the families of src/reference/site_generators.h
      FAMILIES="uniform,equal-weights,lattice,coplanar,collinear,nested,tangent,mixed-sign,duplicates,cospherical,scaled-up,scaled-down,lattice-noise,far-vertices"
    fi
    IFS=, read -r -a families <<<"$FAMILIES"
    for family in "${families[@]}"; do
      if balls=$(generated_balls "$family"); then
        $check_input "$family (n $N, seed $SEED)" "$family-n$N-s$SEED" "$balls"
      else
        echo "| $family (n $N, seed $SEED) | - | generate failed | - | - | - | - | - | - | - | - | - | - | - |"
      fi
    done
  fi
fi
log "outputs, summaries and reports: $WORK_DIR/out/"
