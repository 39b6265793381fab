#!/bin/sh
# 3D Hertz refinement study (docs/deformable.md, "Validation of runs"): makes the sphere's
# meshes at 2, 1.41 and 1 mm at the contact with gmsh (too large to keep in the
# repository: 0.3 to 1.2 MB) and runs the validation test on them (~2 min of CPU).
#   nice -n 19 sh scripts/hertz_sphere_study.sh [BUILD_DIR] [MESHES]
# MESHES (default "2 14 1") may add 07 (0.71 mm, ~10 min) and 05 (0.5 mm, hours: the NLGS
# on ~700 contacts of one body). ctest runs the coarse mesh only
# (tests/validation/data/hertz_sphere_2.msh).
set -e
build=${1:-build}
meshes=${2:-"2 14 1"}
here=$(cd "$(dirname "$0")/.." && pwd)
out="$build/hertz_sphere"
mkdir -p "$out"
rm -f "$out"/hertz_sphere_*.msh
for pair in 2:0.002 14:0.0014142 1:0.001 07:0.00070711 05:0.0005; do
  name=${pair%%:*} sc=${pair#*:}
  case " $meshes " in *" $name "*) ;; *) continue ;; esac
  gmsh "$here/tests/validation/data/hertz_sphere.geo" -3 -setnumber sc "$sc" \
    -format msh41 -bin -o "$out/hertz_sphere_$name.msh" > "$out/gmsh_$name.log"
done
MOREAU_HERTZ_SPHERE_MESHES=$(cd "$out" && pwd) "$build/bin/moreau_test_validation" \
  --gtest_filter='ElasticHertz.SphereOnPlaneRefinementStudy'
