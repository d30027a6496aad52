# Robustness: the verifier's unit tests, the verify_remesh tool, and the tools on the
# hostile inputs of data/hostile. Included at the end of CMakeLists.txt, whose functions
# (conformal_remeshing_add_gtest, conformal_remeshing_add_program_test) and variables (data,
# cgal_meshes) it uses.

conformal_remeshing_add_gtest(test_verifier test_verifier.cpp)

set(hostile ${CMAKE_CURRENT_SOURCE_DIR}/data/hostile)
set(verify ${CMAKE_CURRENT_SOURCE_DIR}/data/verify)
set(verify_dir ${CMAKE_CURRENT_BINARY_DIR}/verify_remesh_out)
file(MAKE_DIRECTORY ${verify_dir})

# --- verify_remesh: exit 0 when every check holds ---------------------------------------------
conformal_remeshing_add_program_test(verify_remesh_mesh_against_itself PROGRAM verify_remesh
  ARGS ${verify}/square.off|${verify}/square.off|--json|${verify_dir}/itself.json
  EXIT 0 OUTPUT "valid: 16 vertices, 18 faces, topology kept: 1 component \\(genus 0; boundary loops 1\\)"
  JSON ${verify_dir}/itself.json
  CHECKS "valid:STREQUAL:ON|checks.topology_kept:STREQUAL:ON|checks.self_intersecting_face_pairs:EQUAL:0|checks.max_distance_to_input:EQUAL:0")
# A bump of 1e-3 passes with a loose enough tolerance (relative to the diagonal, 4.24).
conformal_remeshing_add_program_test(verify_remesh_tolerance PROGRAM verify_remesh
  ARGS ${verify}/square.off|${verify}/square_bump.off|--tolerance|1e-3 EXIT 0 OUTPUT "valid: ")

# --- exit 1 when a check fails: which one, with counts -----------------------------------------
conformal_remeshing_add_program_test(verify_remesh_vertex_off_surface PROGRAM verify_remesh
  ARGS ${verify}/square.off|${verify}/square_bump.off|--json|${verify_dir}/bump.json
  EXIT 1 OUTPUT "INVALID: 1 of 16 vertices off the input surface \\(max distance 0.001"
  JSON ${verify_dir}/bump.json
  CHECKS "valid:STREQUAL:OFF|checks.on_input_surface:STREQUAL:OFF|checks.vertices_off_surface:EQUAL:1|checks.topology_kept:STREQUAL:ON|checks.self_intersection_free:STREQUAL:ON")
conformal_remeshing_add_program_test(verify_remesh_fold PROGRAM verify_remesh
  ARGS ${verify}/square.off|${verify}/square_fold.off|--json|${verify_dir}/fold.json
  EXIT 1 OUTPUT "INVALID: [0-9]+ self-intersecting face pairs"
  JSON ${verify_dir}/fold.json
  CHECKS "checks.self_intersection_free:STREQUAL:OFF|checks.self_intersecting_face_pairs:GREATER:0|checks.on_input_surface:STREQUAL:ON")
conformal_remeshing_add_program_test(verify_remesh_new_hole PROGRAM verify_remesh
  ARGS ${verify}/square.off|${verify}/square_hole.off|--json|${verify_dir}/hole.json
  EXIT 1 OUTPUT "topology changed: input 1 component \\(genus 0; boundary loops 1\\), output 1 component \\(genus 0; boundary loops 2\\)"
  JSON ${verify_dir}/hole.json
  CHECKS "checks.same_boundary_loops:STREQUAL:OFF|checks.same_genera:STREQUAL:ON|output_topology.0.boundary_loops:EQUAL:2")
conformal_remeshing_add_program_test(verify_remesh_dropped_face PROGRAM verify_remesh
  ARGS ${data}/valid_tetrahedron.off|${hostile}/open_tetrahedron.off
  EXIT 1 OUTPUT "topology changed: input 1 component \\(genus 0; boundary loops 0\\), output 1 component \\(genus 0; boundary loops 1\\)")
conformal_remeshing_add_program_test(verify_remesh_output_not_a_mesh PROGRAM verify_remesh
  ARGS ${data}/single_triangle.off|${data}/non_manifold_edge.off
  EXIT 1 OUTPUT "INVALID: output mesh: 1 non-manifold edge")
conformal_remeshing_add_program_test(verify_remesh_output_with_nan PROGRAM verify_remesh
  ARGS ${data}/valid_tetrahedron.off|${hostile}/nan.off
  EXIT 1 OUTPUT "output mesh: 1 vertex with non-finite coordinates.*1 of 4 vertices off the input surface")

# --- exit 2 when it cannot run ----------------------------------------------------------------
conformal_remeshing_add_program_test(verify_remesh_no_argument PROGRAM verify_remesh ARGS "" EXIT 2
  OUTPUT "needs IN and OUT")
conformal_remeshing_add_program_test(verify_remesh_one_argument PROGRAM verify_remesh ARGS ${verify}/square.off EXIT 2
  OUTPUT "needs IN and OUT")
conformal_remeshing_add_program_test(verify_remesh_unknown_option PROGRAM verify_remesh
  ARGS ${verify}/square.off|${verify}/square.off|--bogus EXIT 2 OUTPUT "bad argument '--bogus'")
conformal_remeshing_add_program_test(verify_remesh_bad_tolerance PROGRAM verify_remesh
  ARGS ${verify}/square.off|${verify}/square.off|--tolerance|-1 EXIT 2 OUTPUT "bad argument '--tolerance -1'")
conformal_remeshing_add_program_test(verify_remesh_missing_output PROGRAM verify_remesh
  ARGS ${verify}/square.off|${verify}/no_such_file.off EXIT 2 OUTPUT "cannot read '[^']*no_such_file.off'")
conformal_remeshing_add_program_test(verify_remesh_garbage_input PROGRAM verify_remesh
  ARGS ${hostile}/garbage.stl|${verify}/square.off EXIT 2 OUTPUT "cannot read '[^']*garbage.stl': not a valid STL file")
conformal_remeshing_add_program_test(verify_remesh_input_not_a_mesh PROGRAM verify_remesh
  ARGS ${data}/non_manifold_edge.off|${verify}/square.off EXIT 2 OUTPUT "cannot verify against '[^']*non_manifold_edge.off'")
conformal_remeshing_add_program_test(verify_remesh_input_with_quads PROGRAM verify_remesh
  ARGS ${data}/non_triangle_cube.off|${data}/non_triangle_cube.off EXIT 2 OUTPUT "the input must be a non-empty manifold triangle mesh")
conformal_remeshing_add_program_test(verify_remesh_unwritable_json PROGRAM verify_remesh
  ARGS ${verify}/square.off|${verify}/square.off|--json|${verify_dir}/no/such/dir/x.json EXIT 2 OUTPUT "cannot write")

# --- the remesher's output, verified independently ------------------------------------------------
conformal_remeshing_add_program_test(verify_remesh_run_remesher PROGRAM remesh_conformal_tool
  ARGS ${data}/single_triangle.off|${verify_dir}/single_triangle_remeshed.off|--relative-edge-length|0.05|--quiet EXIT 0)
conformal_remeshing_add_program_test(verify_remesh_remesher_output PROGRAM verify_remesh
  ARGS ${data}/single_triangle.off|${verify_dir}/single_triangle_remeshed.off EXIT 0 OUTPUT "valid: ")
set_tests_properties(verify_remesh_run_remesher PROPERTIES FIXTURES_SETUP remeshed_single_triangle)
set_tests_properties(verify_remesh_remesher_output PROPERTIES FIXTURES_REQUIRED remeshed_single_triangle)
# The default model: a closed part of genus 7, remeshed patch by patch and glued.
conformal_remeshing_add_program_test(verify_remesh_run_remesher_on_default_model PROGRAM remesh_conformal_tool
  ARGS ${PROJECT_SOURCE_DIR}/examples/Conformal_remeshing/data/perforated_plate.off|${verify_dir}/perforated_plate_remeshed.off|--quiet
  EXIT 0)
conformal_remeshing_add_program_test(verify_remesh_remesher_output_on_default_model PROGRAM verify_remesh
  ARGS ${PROJECT_SOURCE_DIR}/examples/Conformal_remeshing/data/perforated_plate.off|${verify_dir}/perforated_plate_remeshed.off|--json|${verify_dir}/perforated_plate.json
  EXIT 0 OUTPUT "valid: .*topology kept: 1 component \\(genus 7; boundary loops 0\\), no self-intersection"
  JSON ${verify_dir}/perforated_plate.json
  CHECKS "checks.topology_kept:STREQUAL:ON|checks.self_intersecting_face_pairs:EQUAL:0|checks.relative_max_distance_to_input:LESS:1e-9")
set_tests_properties(verify_remesh_run_remesher_on_default_model PROPERTIES FIXTURES_SETUP remeshed_default_model)
set_tests_properties(verify_remesh_remesher_output_on_default_model PROPERTIES FIXTURES_REQUIRED remeshed_default_model)

# --- hostile inputs through the tools: a defined exit code and a reason -------------------------
foreach(case IN ITEMS
    "huge_counts.off|not a valid OFF file"
    "huge_face_binary.off|not a valid OFF file"
    "huge_count.ply|not a valid PLY file"
    "property_before_element.ply|not a valid PLY file"
    "truncated_binary.stl|not a valid STL file"
    "garbage_binary.ply|not a valid PLY file")
  string(REPLACE "|" ";" case "${case}")
  list(GET case 0 file)
  list(GET case 1 reason)
  conformal_remeshing_add_program_test(mesh_report_hostile_${file} PROGRAM mesh_report ARGS ${hostile}/${file}
    EXIT 2 OUTPUT "cannot read '[^']*${file}': ${reason}")
endforeach()
foreach(case IN ITEMS
    "nan_binary.ply|1 vertex with non-finite coordinates"
    "collinear_face_1e6.off|1 degenerate \\(zero-area\\) face"
    "pentagon.obj|1 non-triangle face")
  string(REPLACE "|" ";" case "${case}")
  list(GET case 0 file)
  list(GET case 1 reason)
  conformal_remeshing_add_program_test(mesh_report_hostile_${file} PROGRAM mesh_report ARGS ${hostile}/${file}
    EXIT 1 OUTPUT "invalid input '[^']*${file}': ${reason}")
endforeach()
# The remesher triangulates polygons first and says so (--no-repair refuses them), and accepts
# the smallest boundary (a single triangle above).
conformal_remeshing_add_program_test(remesh_conformal_refuses_polygons_without_repair PROGRAM remesh_conformal_tool
  ARGS ${hostile}/quad_and_triangle.ply|${verify_dir}/quad.off|--quiet|--no-repair
  EXIT 1 OUTPUT "invalid input '[^']*': 1 non-triangle face")
conformal_remeshing_add_program_test(remesh_conformal_triangulates_polygons PROGRAM remesh_conformal_tool
  ARGS ${hostile}/quad_and_triangle.ply|${verify_dir}/quad.off|--report|${verify_dir}/quad.json
  EXIT 0 OUTPUT "repaired the input: 1 polygon triangulated into 2 triangles"
  JSON ${verify_dir}/quad.json
  CHECKS "parameters.repair:STREQUAL:ON|input_repairs.triangulated_polygons:EQUAL:1|input_repairs.triangles_from_polygons:EQUAL:2|input_quality.faces:EQUAL:3|fidelity.relative_hausdorff:LESS:0.01")
# User patches name the file's faces: a quad cube's six quads in three patches (its triangles
# take their quad's patch); one id per triangle is refused.
conformal_remeshing_add_program_test(remesh_conformal_patches_of_polygons PROGRAM remesh_conformal_tool
  ARGS ${data}/non_triangle_cube.off|${verify_dir}/cube.off|--patches|${data}/non_triangle_cube_patches.txt|--relative-edge-length|0.1|--report|${verify_dir}/cube.json
  EXIT 0 OUTPUT "6 polygons triangulated into 12 triangles"
  JSON ${verify_dir}/cube.json
  CHECKS "input_repairs.triangulated_polygons:EQUAL:6|input_quality.faces:EQUAL:12|output_quality.minimum_angle.min:GREATER:25|fidelity.relative_hausdorff:LESS:0.01")
conformal_remeshing_add_program_test(remesh_conformal_patches_name_file_faces PROGRAM remesh_conformal_tool
  ARGS ${data}/non_triangle_cube.off|${verify_dir}/cube.off|--patches|${data}/twelve_patch_ids.txt|--quiet
  EXIT 2 OUTPUT "expected 6 non-negative integer patch ids \\(one per face\\), found 12")

# --- time limit: exit code 3, a clear message, and no output file (not even a partial one) ------
# 1 us runs out while reading; 0.5 s runs out inside the remesher (or, on a loaded machine,
# earlier): either way nothing is written. The second remeshes at 0.2% of the diagonal, a
# minute's work: at the default 1% the plate now remeshes within 0.5 s on an idle machine.
conformal_remeshing_add_program_test(remesh_conformal_time_limit PROGRAM remesh_conformal_tool
  ARGS ${PROJECT_SOURCE_DIR}/examples/Conformal_remeshing/data/perforated_plate.off|${verify_dir}/time_limit.off|--time-limit|0.000001|--quiet
  EXIT 3 OUTPUT "remesh_conformal: the time limit of 1e-06 s \\(--time-limit\\) was exceeded; no output written"
  NO_FILE ${verify_dir}/time_limit.off)
conformal_remeshing_add_program_test(remesh_conformal_time_limit_in_the_remesher PROGRAM remesh_conformal_tool
  ARGS ${PROJECT_SOURCE_DIR}/examples/Conformal_remeshing/data/perforated_plate.off|${verify_dir}/time_limit_2.off|--relative-edge-length|0.002|--time-limit|0.5|--quiet
  EXIT 3 OUTPUT "the time limit of 0.5 s \\(--time-limit\\) was exceeded; no output written \\([^)]*stopped"
  NO_FILE ${verify_dir}/time_limit_2.off)
conformal_remeshing_add_program_test(remesh_conformal_bad_time_limit PROGRAM remesh_conformal_tool
  ARGS ${data}/single_triangle.off|${verify_dir}/x.off|--time-limit|-1 EXIT 2 OUTPUT "bad argument '--time-limit'")
