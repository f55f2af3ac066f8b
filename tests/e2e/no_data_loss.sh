#!/usr/bin/env bash
# No data loss: a frame that fails keeps every completed frame's file whole and leaves none partial;
# --keep-going renders the rest; a multi-page file is whole or absent; a full disk or an unwritable
# folder is a clear error that damages no earlier file.
#   no_data_loss.sh HLRSCRIPT WORK
set -uo pipefail
hlrscript=$1
work=$2
rm -rf "$work" "$work.log"
mkdir -p "$work" "$work.log"
cd "$work" || exit 1
out=$work.log/out.txt err=$work.log/err.txt

failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}
# run EXIT ARGS...: runs hlrscript, checks the status; the streams are in $out and $err.
run() {
  local status=$1
  shift
  "$hlrscript" "$@" >"$out" 2>"$err"
  local code=$?
  [ "$code" = "$status" ] || fail "hlrscript $*: exit $code, expected $status: $(cat "$err")"
}
says() { grep -qF -- "$1" "$err" || fail "stderr lacks '$1': $(cat "$err")"; }
only_files() {  # the folder holds exactly these names (no temporary file either)
  local want have
  want=$(printf '%s\n' "$@" | sort)
  have=$(ls -A | sort)
  [ "$want" = "$have" ] || fail "files: expected [$(echo $want)], have [$(echo $have)]"
}
valid_svgs() {
  for f in "$@"; do rsvg-convert "$f" >/dev/null 2>&1 || fail "$f is not a whole SVG"; done
}

# Frames 3 and 5 fail (an index out of range); the others draw a turning box.
cat >seq.hls <<'EOF'
animate frames 6
camera c = lookat(eye: (4, -3, 3), target: (0, 0, 0.5))
draw box(1, 1, 1) at rotate(z: 10 * frame)
if frame == 3 or frame == 5 { let x = [1, 2][7] }
EOF

# ---- a file per frame: the frames before the failure stay, whole; nothing after it ----
for jobs in 1 2; do
  run 65 seq.hls -o 'f-{frame}.svg' --jobs "$jobs"
  says "seq.hls:4:46: error: index 7 is out of range for 2 items (in frame 3)"
  says "frame 3 of 6 failed; kept 3 complete files (frames 0-2), none partial"
  says "--frames 3-5 renders the rest"
  only_files seq.hls f-0.svg f-1.svg f-2.svg
  valid_svgs f-0.svg f-1.svg f-2.svg
  rm -f f-*.svg
done

# ---- --keep-going: every frame that can be drawn is ----
run 65 seq.hls -o 'f-{frame}.svg' --keep-going
says "(in frame 3)"
says "(in frame 5)"
says "frames 3,5 of 6 failed; kept 4 complete files (frames 0-2,4), none partial"
only_files seq.hls f-0.svg f-1.svg f-2.svg f-4.svg
valid_svgs f-0.svg f-1.svg f-2.svg f-4.svg
rm -f f-*.svg

# ---- a script's own per-frame names (known only once the frame is evaluated) ----
sed 's/^animate frames 6$/animate frames 6\noutput "s-{frame}.pdf"/' seq.hls >named.hls
run 65 named.hls --keep-going
only_files seq.hls named.hls s-0.pdf s-1.pdf s-2.pdf s-4.pdf
for f in s-0.pdf s-1.pdf s-2.pdf s-4.pdf; do
  pdfinfo "$f" >/dev/null 2>&1 || fail "$f is not a whole PDF"
done
rm -f s-*.pdf named.hls

# ---- one multi-page file: whole or absent, and an earlier one is left as it was ----
printf 'an earlier all.pdf\n' >all.pdf
cp all.pdf "$work.log/before.pdf"
run 65 seq.hls -o all.pdf --keep-going
says "kept 0 complete files"
cmp -s all.pdf "$work.log/before.pdf" || fail "all.pdf was changed"
only_files seq.hls all.pdf
rm -f all.pdf

# ---- a full disk (a file size limit, which fails writes as a full disk does) ----
# Frame 2 draws a finely divided sphere, so its PNG is many times the others'; the limit lets the small
# ones through. An f-2.png from an earlier run must survive untouched.
cat >big.hls <<'EOF'
animate frames 3
camera c = lookat(eye: (4, -3, 3), target: (0, 0, 0.5))
draw box(1, 1, 1)
if frame == 2 { draw sphere(1.2, 96, 48, crease: 0) at translate(0, 0, 0.5) }
EOF
printf 'an earlier frame 2\n' >f-2.png
cp f-2.png "$work.log/before.png"
(
  ulimit -f 32        # KiB: frames 0 and 1 take about 16, frame 2 about 140
  trap '' XFSZ        # a write past the limit fails with EFBIG instead of killing the process
  "$hlrscript" big.hls -o 'f-{frame}.png' --jobs 1 >"$out" 2>"$err"
  echo $? >"$work.log/code"
)
[ "$(cat "$work.log/code")" = 73 ] || fail "full disk: exit $(cat "$work.log/code"), expected 73: $(cat "$err")"
says "cannot write 'f-2.png'"
says "File too large"
says "kept 2 complete files (frames 0-1)"
cmp -s f-2.png "$work.log/before.png" || fail "the earlier f-2.png was changed"
only_files seq.hls big.hls f-0.png f-1.png f-2.png
rm -f f-*.png

# ---- a folder no file can be created in ----
run 73 seq.hls -o /proc/hlrscript-test.svg --frames 0
says "cannot write '/proc/hlrscript-test.svg': cannot create a file in '/proc'"
if [ "$(id -u)" != 0 ]; then  # root writes into a read-only folder anyway
  mkdir ro && chmod 555 ro
  run 73 seq.hls -o 'ro/f-{frame}.svg' --frames 0-2
  says "cannot write 'ro/f-0.svg': cannot create a file in 'ro': Permission denied"
  [ -z "$(ls -A ro)" ] || fail "ro/ is not empty"
  chmod 755 ro && rmdir ro
fi

rm -rf "$work.log"
if [ "$failures" -gt 0 ]; then
  echo "$failures failures"
  exit 1
fi
echo "no data loss: completed frames kept whole, nothing partial, earlier files untouched"
