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
# Skips (exit 0, saying so) when the models or the skeleton are absent.
# Exit status: 0 when every file passed, 1 when one did (listed).
tool=$1 asf=$2 models=${3:-/usr/share/assimp/models} limit=${4:-120}
[ -x "$tool" ] || { echo "import sweep: $tool is not built"; exit 1; }
if [ ! -d "$models" ] || [ ! -f "$asf" ]; then
	echo "import sweep: skipped (no $models: apt-get install assimp-testmodels; or no $asf)"
	exit 0
fi
scratch=$(mktemp -d /tmp/skp_sweep_XXXXXX) || exit 1
trap 'rm -rf "$scratch"' EXIT
files=0 bound=0 refused=0 failed=""
list="$scratch/files"
find "$models" -type f \( -iname '*.gltf' -o -iname '*.glb' -o -iname '*.fbx' -o -iname '*.dae' \
	-o -iname '*.obj' -o -iname '*.x' -o -iname '*.3ds' -o -iname '*.ply' -o -iname '*.blend' \
	-o -iname '*.stl' -o -iname '*.ms3d' -o -iname '*.smd' -o -iname '*.md5mesh' \) | sort > "$list"
total=$(wc -l < "$list")
while IFS= read -r f; do
	files=$((files + 1))
	for weights in own computed; do
		set -- -o "$scratch/w.csv"
		[ $weights = own ] && set -- "$@" --weights mesh
		rm -f "$scratch/w.csv"
		timeout "$limit" "$tool" bind --quiet "$asf" "$f" "$@" > /dev/null 2> "$scratch/err"
		rc=$?
		why=""
		if grep -qE 'Sanitizer|runtime error' "$scratch/err"; then
			why="sanitizer: $(grep -m1 -E 'Sanitizer|runtime error' "$scratch/err")"
		elif [ $rc = 124 ]; then
			why="no answer in $limit s"
		elif [ $rc -gt 128 ]; then
			why="killed by signal $((rc - 128))"
		elif [ $rc = 0 ] && [ ! -s "$scratch/w.csv" ]; then
			why="exit 0 without weights"
		elif [ $rc = 1 ] && ! tail -n 1 "$scratch/err" | grep -qF "$f"; then
			why="exit 1, last line not naming the file: $(tail -n 1 "$scratch/err")"
		elif [ $rc = 1 ] && [ -e "$scratch/w.csv" ]; then
			why="exit 1 with a weights file written"
		elif [ $rc != 0 ] && [ $rc != 1 ]; then
			why="exit $rc"
		fi
		if [ -n "$why" ]; then
			failed="$failed
  $f ($weights weights): $why"
		elif [ $rc = 0 ]; then
			bound=$((bound + 1))
		else
			refused=$((refused + 1))
		fi
	done
	[ $((files % 25)) = 0 ] && echo "import sweep: $files of $total files" >&2
done < "$list"
echo "import sweep: $files files from $models, twice each (own and computed weights): $bound bound," \
	"$refused refused with a message naming the file"
if [ -n "$failed" ]; then
	echo "import sweep: FAILED:$failed"
	exit 1
fi
echo "import sweep: no crash, no hang, no sanitizer report"
