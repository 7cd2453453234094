#!/bin/sh
# The portable core (and the frame's path above it, WHAT="runtime and
# setup objects") must not allocate or use stdio: list any object that
# references such a symbol and fail.
forbidden='^(malloc|calloc|realloc|free|strdup|strndup|aligned_alloc|posix_memalign|printf|fprintf|sprintf|snprintf|vprintf|vfprintf|vsprintf|vsnprintf|dprintf|puts|fputs|fputc|putc|putchar|fopen|fdopen|freopen|fclose|fread|fwrite|fgets|fgetc|getc|getchar|fflush|fseek|ftell|rewind|perror|scanf|fscanf|sscanf|stdin|stdout|stderr|setvbuf|__.*printf_chk|__.*sprintf_chk)$'
bad=0
for o in "$@"; do
	syms=$(nm -u "$o" | awk '{print $NF}' | sed 's/@.*//' | grep -E "$forbidden" | tr '\n' ' ')
	if [ -n "$syms" ]; then
		echo "check-core: $o references $syms"
		bad=1
	fi
done
[ $bad -eq 0 ] && echo "check-core: $# ${WHAT:-core objects} use no allocation and no stdio"
exit $bad
