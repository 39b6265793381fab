#!/bin/sh
# 3D Hertz refinement study (docs/deformable.md, "Validation of runs"): makes the sphere's
# meshes at 2, 1 and 0.5 mm at the contact with gmsh (the two finer ones are too large to
# keep in the repository: 1.2 MB and 6.9 MB) and runs the validation test on them.
#   nice -n 19 sh scripts/hertz_sphere_study.sh [BUILD_DIR]     (default: build)
# ctest runs the coarse mesh only (tests/validation/data/hertz_sphere_2.msh).
set -e
build=${1:-build}
here=$(cd "$(dirname "$0")/.." && pwd)
out="$build/hertz_sphere"
mkdir -p "$out"
for pair in 2:0.002 1:0.001 05:0.0005; do
  name=${pair%%:*} sc=${pair#*:}
  gmsh "$here/tests/validation/data/hertz_sphere.geo" -3 -setnumber sc "$sc" \
    -format msh41 -bin -o "$out/hertz_sphere_$name.msh" > "$out/gmsh_$name.log"
done
MOREAU_HERTZ_SPHERE_MESHES=$(cd "$out" && pwd) "$build/bin/moreau_test_validation" \
  --gtest_filter='ElasticHertz.SphereOnPlaneRefinementStudy'
