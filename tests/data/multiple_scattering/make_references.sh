#!/usr/bin/env bash
# The judge's multiple-scattering images the real-time tests compare against
# (tests/scenes/media/multiple_scattering_test.cpp): each scene at the time the tests use, 96x54,
# seed 1, and each pixel's standard error beside it. The water clouds (albedo 0.999, g 0.85) take
# 256 paths per pixel (the field 128: its thick clouds make long paths), the rest 128.
# Usage: tests/data/multiple_scattering/make_references.sh [path/to/sandbox] [scene ...]
set -euo pipefail
cd "$(dirname "$0")"
sandbox=${1:-../../../build/release/bin/sandbox}
shift || true
entries=(cumulus:0:256 cloud:0:256 cumulus_aircraft:0:256 cumulus_field:0:128 steam:8:256 smoke:8:128 campfire:4:128 jet:6:128
         explosion:0.8:128 fog_smoke:8:128)
for entry in "${entries[@]}"; do
  IFS=: read -r scene time spp <<<"$entry"
  if [ $# -gt 0 ] && [[ ! " $* " =~ " $scene " ]]; then continue; fi
  "$sandbox" reference "../../../content/scenes/$scene.gltf" --time "$time" --size 96x54 --spp "$spp" --seed 1 \
    --scattering multiple --out "$scene.exr"
done
