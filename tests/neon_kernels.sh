# Sourced by tests/count_insns.sh and tests/model_cycles.sh: the NEON
# kernels they measure and how each is compared (DQBS with LBS, fixed with
# float DQBS, compact with float), in one place.
NEON_KERNELS="skin_lbs_neon skin_dqbs_neon skin_dqbs_fixed_neon skin_lbs_compact_neon skin_dqbs_compact_neon"

# Reads "kernel column value" lines and prints them with value / the value
# of the kernel it is compared with. $1: the header line; $2: printf format
# of one row's kernel, column and value.
neon_table() {
	awk -v head="$1" -v row="$2" '
	BEGIN { print head
		base["skin_dqbs_neon"] = "skin_lbs_neon"; base["skin_dqbs_fixed_neon"] = "skin_dqbs_neon"
		base["skin_lbs_compact_neon"] = "skin_lbs_neon"; base["skin_dqbs_compact_neon"] = "skin_dqbs_neon" }
	{ v[$1] = $3; b = base[$1]
	  r = ($1 in base && v[b] > 0) ? sprintf("%.2fx %s", $3 / v[b], b) : ""
	  printf row "  %s\n", $1, $2, $3, r }'
}
