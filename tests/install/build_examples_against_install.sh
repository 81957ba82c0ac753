#!/usr/bin/env bash
# Install test: installs Signorini into a scratch prefix; checks that exactly the public
# headers are installed and that each compiles on its own; runs the installed program on
# xml/default.xml, examples/bodies and a mesh in parts; runs the Python example with the installed module;
# builds every C++ example against the exported CMake package and runs it on 2 MPI ranks.
set -euo pipefail
source_dir=$1
build_dir=$2
work=$build_dir/install-test
rm -rf "$work"
mkdir -p "$work"
cmake --install "$build_dir" --prefix "$work/prefix" > "$work/install.log" 2>&1 || { cat "$work/install.log"; exit 1; }

# The public headers, and only they: include/signorini/ plus the generated version header.
diff <(cd "$work/prefix/include" && find signorini -name '*.hpp' | sort) \
     <( (cd "$source_dir/include" && find signorini -name '*.hpp'; echo signorini/core/Version.hpp) | sort) ||
  { echo "the installed headers differ from include/signorini/ (< installed, > expected)"; exit 1; }

# The installed program runs from the prefix alone (it finds the installed library) and
# solves the shipped default problem.
(cd "$work" && mpiexec -np 2 "$work/prefix/bin/signorini" "$source_dir/xml/default.xml" --output "$work/default") ||
  { echo "the installed bin/signorini does not solve xml/default.xml"; exit 1; }
test -s "$work/default/summary.json"

# A part of two materials from a Gmsh geometry (Problem/Bodies), force controlled: the
# contact carries the load, and the output names each cell's body.
(cd "$work" && mpiexec -np 2 "$work/prefix/bin/signorini" "$source_dir/examples/bodies/padded-block-2d.xml" \
   --output "$work/padded-block") || { echo "the installed bin/signorini does not solve examples/bodies"; exit 1; }
/usr/bin/python3 - "$work/padded-block/summary.json" <<'CHECK'
import json, sys
summary = json.load(open(sys.argv[1]))
force = summary["contact"]["normal_force"]
assert summary["status"] == "converged" and abs(force - 80.0) < 1e-6 * 80.0, (summary["status"], force)
CHECK
grep -q 'Name="body"' "$work/padded-block/solution_0.vtu" || { echo "no body field in the padded block's output"; exit 1; }
# Two bodies meshed apart in mortar contact, the upper one held by the contact alone (2D and
# 3D): the contact pressure is the applied one.
for dim in 2d 3d; do
  (cd "$work" && mpiexec -np 2 "$work/prefix/bin/signorini" "$source_dir/examples/bodies/two-blocks-$dim.xml" \
     --output "$work/two-blocks-$dim") || { echo "the installed bin/signorini does not solve the two blocks ($dim)"; exit 1; }
  /usr/bin/python3 - "$work/two-blocks-$dim/summary.json" <<'CHECK'
import json, sys
contact = json.load(open(sys.argv[1]))["contact"]
assert abs(contact["normal_force"] - 0.01) < 1e-8 and abs(contact["peak_pressure"] - 0.01) < 1e-8, contact
CHECK
done
# Two contact pairs, the base on the rigid ground and the block on the base: each carries the load.
(cd "$work" && mpiexec -np 2 "$work/prefix/bin/signorini" "$source_dir/examples/bodies/blocks-on-the-ground-2d.xml" \
   --output "$work/blocks-on-the-ground") || { echo "the installed bin/signorini does not solve two contact pairs"; exit 1; }
/usr/bin/python3 - "$work/blocks-on-the-ground/summary.json" <<'CHECK'
import json, sys
pairs = json.load(open(sys.argv[1]))["contact"]["pairs"]
assert [p["name"] for p in pairs] == ["floor", "interface"], pairs
for p in pairs:
    assert abs(p["normal_force"] - 0.01) < 1e-8 and abs(p["peak_pressure"] - 0.01) < 1e-8, p
assert "master_force" in pairs[1] and abs(pairs[1]["master_force"][1] + pairs[1]["force"][1]) < 1e-10, pairs[1]
CHECK

# A Gmsh mesh written in two parts by the gmsh program, each rank reading its own: the same
# problem as the mesh read whole.
gmsh "$source_dir/examples/hertz/half-ball-3d.geo" -3 -o "$work/ball.msh" > /dev/null
gmsh "$work/ball.msh" -part 2 -part_split -o "$work/ball-in-parts.msh" -save > /dev/null
for mesh in ball ball-in-parts; do
  (cd "$work" && mpiexec -np 2 "$work/prefix/bin/signorini" "$source_dir/examples/hertz/half-ball-3d.xml" \
     --set "Problem/mesh: file=$work/$mesh.msh" --set "Output/write solution=false" --output "$work/$mesh") ||
    { echo "the installed bin/signorini does not solve the half-ball from $mesh.msh"; exit 1; }
done
/usr/bin/python3 - "$work/ball/summary.json" "$work/ball-in-parts/summary.json" <<'CHECK'
import json, sys
whole, parts = (json.load(open(f)) for f in sys.argv[1:])
assert (whole["n"], whole["m"]) == (parts["n"], parts["m"]), (whole["n"], whole["m"], parts["n"], parts["m"])
assert abs(parts["objective"] - whole["objective"]) <= 1e-9 * abs(whole["objective"]), (parts["objective"], whole["objective"])
assert parts["serial_mesh_mib"] == 0, parts["serial_mesh_mib"]
CHECK

# The installed Python module, from the prefix alone: the hand-over example.
(cd "$work" && PYTHONPATH="$work/prefix/lib/python3/dist-packages" /usr/bin/python3 \
   "$source_dir/examples/python-handover/handover.py" "$work/handover-pressure.png") ||
  { echo "the installed Python module does not solve examples/python-handover"; exit 1; }

cmake -S "$source_dir/tests/install/installed_headers" -B "$work/headers" -DCMAKE_PREFIX_PATH="$work/prefix"
cmake --build "$work/headers" -j 2

# Each example, configured with only CMAKE_PREFIX_PATH, built and run on 2 ranks.
build_example() {
  cmake -S "$source_dir/examples/$1" -B "$work/$1" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$work/prefix"
  cmake --build "$work/$1" -j 2
}
build_example obstacle-membrane
mpiexec -np 2 "$work/obstacle-membrane/obstacle_membrane" 31
build_example paper-pipeline
mpiexec -np 2 "$work/paper-pipeline/paper_pipeline" "$source_dir/xml/paper/H.xml" "$work/paper-pipeline/output"
test -s "$work/paper-pipeline/output/solution.pvtu"
build_example hertz-gmsh
mpiexec -np 2 "$work/hertz-gmsh/hertz_gmsh" "$source_dir/examples/hertz/half-disk-2d.geo" 0.5
mpiexec -np 2 "$work/hertz-gmsh/hertz_gmsh" "$source_dir/examples/hertz/half-disk-2d.geo" 1 1
build_example two-bodies
two_bodies=$(mpiexec -np 2 "$work/two-bodies/two_bodies" "$source_dir/examples/bodies/disk-on-block-2d.geo" 100) ||
  { echo "the two-bodies example does not solve"; exit 1; }
echo "$two_bodies"
echo "$two_bodies" | awk '/imbalance/ { found = 1; if ($(NF - 3) + 0 > 1e-10) exit 1 } END { if (!found) exit 1 }' ||
  { echo "two_bodies: action and reaction do not balance to 1e-10"; exit 1; }
