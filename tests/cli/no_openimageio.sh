#!/usr/bin/env bash
# no_openimageio.sh MODULE EXECUTABLE...
# OpenImageIO (and its ~270 libraries) must be loaded only with the image codec module, on the
# first image: no executable may need it, directly (readelf -d) or through another library
# (ldd). The module itself must need it, or this test would check nothing.
set -u
module="$1"; shift
readelf -d "$module" | grep NEEDED | grep -qi openimageio ||
  { echo "$module does not need OpenImageIO: is it the codec module?"; exit 1; }
status=0
for exe in "$@"; do
  if readelf -d "$exe" | grep NEEDED | grep -i openimageio; then
    echo "$exe needs OpenImageIO directly"; status=1
  elif ldd "$exe" | grep -i openimageio; then
    echo "$exe loads OpenImageIO through another library"; status=1
  else
    echo "ok: $exe: $(ldd "$exe" | grep -c '=>') libraries, no OpenImageIO"
  fi
done
exit $status
