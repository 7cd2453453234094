#!/bin/sh
# The portable core (and the frame's path above it, WHAT="runtime and
# setup objects") must not allocate or use stdio: list any object that
# references such a symbol and fail. One nm for every object (a process
# an object took ten seconds).
forbidden='^(malloc|calloc|realloc|free|strdup|strndup|aligned_alloc|posix_memalign|printf|fprintf|sprintf|snprintf|vprintf|vfprintf|vsprintf|vsnprintf|dprintf|puts|fputs|fputc|putc|putchar|fopen|fdopen|freopen|fclose|fread|fwrite|fgets|fgetc|getc|getchar|fflush|fseek|ftell|rewind|perror|scanf|fscanf|sscanf|stdin|stdout|stderr|setvbuf|__.*printf_chk|__.*sprintf_chk)$'
[ $# -gt 0 ] || exit 0
nm -A -u "$@" | awk -v re="$forbidden" -v n=$# -v what="${WHAT:-core objects}" '
	{
		o = $1; sub(/:$/, "", o)
		sym = $NF; sub(/@.*/, "", sym)
		if (sym ~ re) {
			if (!(o in refs)) order[++count] = o
			refs[o] = refs[o] sym " "
		}
	}
	END {
		for (i = 1; i <= count; i++)
			print "check-core: " order[i] " references " refs[order[i]]
		if (count) exit 1
		print "check-core: " n " " what " use no allocation and no stdio"
	}'
