#!/bin/sh
# libvct.so exports exactly the functions the public headers declare (each
# marked VCT_API): no internal function leaks into the shared library's
# symbol table, and none of the documented ones is missing from it.
# Usage: test_exports.sh LIBVCT_SO INCLUDE_DIR
set -u
LIB=$1
INCLUDE=$2
DIR=$(mktemp -d)
trap 'rm -rf "$DIR"' EXIT
nm -D --defined-only "$LIB" | awk '$2 == "T" { print $3 }' | sort >"$DIR/exported"
grep -h "^VCT_API" "$INCLUDE"/vct/*.h | grep -o "vct_[a-z0-9_]*(" | tr -d '(' | sort -u >"$DIR/declared"
count=$(wc -l <"$DIR/declared")
extra=$(comm -23 "$DIR/exported" "$DIR/declared")
missing=$(comm -13 "$DIR/exported" "$DIR/declared")
failures=0
if [ -n "$extra" ]; then
    echo "FAIL exported but not declared in a public header:"; echo "$extra"; failures=1
fi
if [ -n "$missing" ]; then
    echo "FAIL declared VCT_API but not exported:"; echo "$missing"; failures=1
fi
# Every function declaration of the public headers is marked VCT_API.
unmarked=$(grep -hE "^[a-z].*\bvct_[a-z0-9_]+\(" "$INCLUDE"/vct/*.h | grep -v "^typedef")
if [ -n "$unmarked" ]; then
    echo "FAIL public declarations without VCT_API:"; echo "$unmarked"; failures=1
fi
[ "$count" -gt 100 ] || { echo "FAIL only $count declarations read"; failures=1; }
[ $failures -eq 0 ] && echo "ok   libvct.so exports the $count documented functions and nothing else"
echo "$failures failed"
exit $failures
