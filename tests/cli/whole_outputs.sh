#!/usr/bin/env bash
# whole_outputs.sh DIR LIMIT_KB COMMAND...: outputs stay whole when writing fails part-way.
# COMMAND (without --out) runs three times, into DIR/ref without a limit, then with a file-size
# limit of LIMIT_KB (the shell's `ulimit -f`) as the stand-in for a full disk:
# - "full": SIGXFSZ ignored, so a write past the limit fails (EFBIG, as ENOSPC would): the command
#   must exit with code 1 and say "cannot write" and why;
# - "killed": SIGXFSZ's default action kills the command in the middle of its first write past
#   the limit, into a directory that already holds a complete earlier run.
# Both times every file under a final name (hidden temporaries aside) must be whole: identical to
# the reference run's (JSON reports, which hold timings, must end as the reference's does and be
# at least 90 % of its size), and after "killed" no file of the earlier run may be missing.
set -u
dir=$1; limit=$2; shift 2
ref=$dir/ref; full=$dir/full; killed=$dir/killed
rm -rf "$ref" "$full" "$killed"
"$@" --out "$ref" >/dev/null || { echo "whole_outputs.sh: the reference run failed" >&2; exit 1; }

whole() { # whole DIR: every final-named file of DIR is the reference's
  local f name
  for f in "$1"/*; do
    [ -e "$f" ] || continue
    name=$(basename "$f")
    [ -e "$ref/$name" ] || { echo "whole_outputs.sh: $name is not in the reference" >&2; return 1; }
    case "$name" in
      *.json)
        if [ "$(tail -c 2 "$f" | od -An -c)" != "$(tail -c 2 "$ref/$name" | od -An -c)" ] ||
           [ $(($(wc -c <"$f") * 10)) -lt $(($(wc -c <"$ref/$name") * 9)) ]; then
          echo "whole_outputs.sh: $1/$name is cut short" >&2; return 1
        fi ;;
      *) cmp -s "$f" "$ref/$name" || { echo "whole_outputs.sh: $1/$name is not whole" >&2; return 1; } ;;
    esac
  done
}

# The limit must cut some file of the run short, or nothing is tested.
largest=$(wc -c "$ref"/* | sort -n | tail -2 | head -1 | awk '{print $1}')
[ "$largest" -gt $((limit * 1024)) ] || { echo "whole_outputs.sh: limit above every file" >&2; exit 1; }

out=$( (trap '' XFSZ; ulimit -f "$limit"; "$@" --out "$full") 2>&1); rc=$?
if [ "$rc" -ne 1 ] || ! printf '%s' "$out" | grep -q "cannot write .*: File too large"; then
  printf '%s\n' "$out"; echo "whole_outputs.sh: full disk: exit code $rc, expected 1 and 'cannot write'" >&2
  exit 1
fi
whole "$full" || exit 1

cp -r "$ref" "$killed"
(ulimit -f "$limit"; exec "$@" --out "$killed" >/dev/null 2>&1); rc=$?
[ "$rc" -eq $((128 + 25)) ] || { echo "whole_outputs.sh: killed run exit code $rc, expected 153 (SIGXFSZ)" >&2; exit 1; }
whole "$killed" || exit 1
for f in "$ref"/*; do
  [ -e "$killed/$(basename "$f")" ] || { echo "whole_outputs.sh: $(basename "$f") went missing" >&2; exit 1; }
done
echo "whole_outputs.sh: outputs whole after a full disk and a kill ($limit KB limit)"
