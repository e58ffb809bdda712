#!/usr/bin/env bash
# The judge's multiple-scattering images the real-time tests compare against
# (tests/scenes/media/multiple_scattering_test.cpp): each content scene at the time the content
# tests use, 96x54, 128 paths per pixel, seed 1, and each pixel's standard error beside it.
# Usage: tests/data/multiple_scattering/make_references.sh [path/to/sandbox]
set -euo pipefail
cd "$(dirname "$0")"
sandbox=${1:-../../../build/release/bin/sandbox}
for entry in cumulus:0 cloud:0 cumulus_aircraft:0 smoke:8 campfire:4 jet:6 explosion:0.8 fog_smoke:8; do
  scene=${entry%%:*} time=${entry##*:}
  "$sandbox" reference "../../../content/scenes/$scene.gltf" --time "$time" --size 96x54 --spp 128 --seed 1 \
    --scattering multiple --out "$scene.exr"
done
