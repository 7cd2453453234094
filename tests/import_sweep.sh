#!/bin/sh
# Every sample model Debian's assimp-testmodels ships (glTF, FBX, COLLADA,
# OBJ, 3DS, PLY, X, Blender, ...: real files, broken ones among them)
# through `skintool bind`, with the mesh's own weights and with computed
# ones, in a build with ASan and UBSan. Each run must either bind (exit 0,
# weights written) or refuse (exit 1, its last line naming the file, no
# weights file left), within the time limit, with no sanitizer report.
#
#   tests/import_sweep.sh SKINTOOL SKELETON.asf [MODELS_DIR] [SECONDS]
#
# SKP_SWEEP_JOBS files at a time (default: the machine's processors); the
# slowest files of the last run start first (their times kept in
# SKINTOOL's directory, import_sweep.times), so the run ends when its
# longest file does. Skips (exit 0, saying so) when the models or the
# skeleton are absent. Exit status: 0 when every file passed, 1 when one
# did (listed).

# one file, both weights (import_sweep.sh --one FILE): one verdict line a
# run in $scratch/verdicts ("bound", "refused" or "failed: why"), the
# file's time in $scratch/times, progress every 25 files
if [ "$1" = --one ]; then
	f=$2 work=$(mktemp -d "$scratch/one_XXXXXX") s=$(date +%s.%N)
	for weights in own computed; do
		set -- -o "$work/w.csv"
		[ $weights = own ] && set -- "$@" --weights mesh
		timeout "$limit" "$tool" bind --quiet "$asf" "$f" "$@" > /dev/null 2> "$work/err"
		rc=$?
		why=""
		if grep -qE 'Sanitizer|runtime error' "$work/err"; then
			why="sanitizer: $(grep -m1 -E 'Sanitizer|runtime error' "$work/err")"
		elif [ $rc = 124 ]; then
			why="no answer in $limit s"
		elif [ $rc -gt 128 ]; then
			why="killed by signal $((rc - 128))"
		elif [ $rc = 0 ] && [ ! -s "$work/w.csv" ]; then
			why="exit 0 without weights"
		elif [ $rc = 1 ] && ! tail -n 1 "$work/err" | grep -qF "$f"; then
			why="exit 1, last line not naming the file: $(tail -n 1 "$work/err")"
		elif [ $rc = 1 ] && [ -e "$work/w.csv" ]; then
			why="exit 1 with a weights file written"
		elif [ $rc != 0 ] && [ $rc != 1 ]; then
			why="exit $rc"
		fi
		if [ -n "$why" ]; then
			verdict="failed: $f ($weights weights): $why"
		elif [ $rc = 0 ]; then
			verdict=bound
		else
			verdict=refused
		fi
		rm -f "$work/w.csv"
		flock "$scratch/lock" sh -c 'echo "$1" >> "$2/verdicts"' sh "$verdict" "$scratch"
	done
	rm -rf "$work"
	t=$(awk -v s="$s" -v e="$(date +%s.%N)" 'BEGIN { printf "%.1f", e - s }')
	flock "$scratch/lock" sh -c 'printf "%s\t%s\n" "$1" "$2" >> "$3/times"
		n=$(wc -l < "$3/times"); [ $((n % 25)) = 0 ] && echo "import sweep: $n of $4 files" >&2; :' \
		sh "$t" "$f" "$scratch" "$total"
	exit 0
fi

tool=$1 asf=$2 models=${3:-/usr/share/assimp/models} limit=${4:-120}
[ -x "$tool" ] || { echo "import sweep: $tool is not built"; exit 1; }
if [ ! -d "$models" ] || [ ! -f "$asf" ]; then
	echo "import sweep: skipped (no $models: apt-get install assimp-testmodels; or no $asf)"
	exit 0
fi
jobs=${SKP_SWEEP_JOBS:-$(nproc 2>/dev/null || echo 1)}
times=$(dirname "$tool")/import_sweep.times
scratch=$(mktemp -d /tmp/skp_sweep_XXXXXX) || exit 1
trap 'rm -rf "$scratch"' EXIT
start=$(date +%s)
: > "$scratch/verdicts"
: > "$scratch/times"
find "$models" -type f \( -iname '*.gltf' -o -iname '*.glb' -o -iname '*.fbx' -o -iname '*.dae' \
	-o -iname '*.obj' -o -iname '*.x' -o -iname '*.3ds' -o -iname '*.ply' -o -iname '*.blend' \
	-o -iname '*.stl' -o -iname '*.ms3d' -o -iname '*.smd' -o -iname '*.md5mesh' \) | sort > "$scratch/files"
total=$(wc -l < "$scratch/files")
sh "$(dirname "$0")/slowest_first.sh" "$times" < "$scratch/files" | tr '\n' '\0' |
	scratch=$scratch tool=$tool asf=$asf limit=$limit total=$total \
	xargs -0 -P "$jobs" -n 1 sh "$0" --one
sort -t "$(printf '\t')" -k2 "$scratch/times" > "$times.new" && mv "$times.new" "$times"
bound=$(grep -c '^bound$' "$scratch/verdicts")
refused=$(grep -c '^refused$' "$scratch/verdicts")
failed=$(sed -n 's/^failed: /  /p' "$scratch/verdicts")
echo "import sweep: $total files from $models, twice each (own and computed weights): $bound bound," \
	"$refused refused with a message naming the file; $jobs at a time, $(($(date +%s) - start)) s"
echo "import sweep: slowest: $(sort -g -r -k1,1 "$scratch/times" | head -n 3 | awk -F '\t' '{ printf "%s%s %s s", (NR > 1 ? ", " : ""), $2, $1 }')"
if [ -n "$failed" ] || [ $((bound + refused)) != $((2 * total)) ]; then
	echo "import sweep: FAILED:${failed:- $((bound + refused)) of $((2 * total)) runs gave a verdict}"
	exit 1
fi
echo "import sweep: no crash, no hang, no sanitizer report"
