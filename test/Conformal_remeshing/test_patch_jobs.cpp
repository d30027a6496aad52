// Patch jobs: each patch meshed from one value that holds all it reads (patch_job.h), the
// meshing stage's reuse of the results of equal jobs, and jobs and results as bytes for other
// processes (patch_job_io.h).

#include "off_text.h"
#include "stage_tests.h"

#include <CGAL/Conformal_remeshing/internal/remeshing/patch_job_io.h>

#include <sstream>

namespace {

// The shipped perforated plate, segmented and flattened, its boundary curves sampled at the
// default target length.
struct Plate_patches
{
  RM::Flattened_surface surface;
  std::unique_ptr<RM::Sizing> sizing;
  RM::Curve_samples samples;
  std::vector<std::vector<std::size_t> > neighbours;
  RM::Patch_meshing meshing;

  explicit Plate_patches(const std::vector<int>& halvings = {})
  {
    Mesh plate;
    EXPECT_TRUE(CGAL::IO::read_polygon_mesh(std::string(CONFORMAL_REMESHING_EXAMPLE_DATA) + "/perforated_plate.off", plate));
    const auto np = CGAL::parameters::default_values();
    const RM::Remeshing_options options = RM::remeshing_options(plate, np);
    CR::Remeshing_report report;
    CR::Remeshing_statistics statistics;
    RM::segment_and_flatten<CGAL::Sequential_tag>(plate, options, np, CR::internal::Time_limit::from(np, "test"),
                                                  [](const std::string&) {}, report, statistics, surface);
    sizing.reset(new RM::Sizing(surface.segmentation, options.target_edge_length));
    samples = RM::sample_boundary_curves(surface.segmentation, *sizing, options.corner_angle, halvings);
    neighbours = RM::chord_neighbours(samples);
    meshing.minimum_angle = options.minimum_angle;
    meshing.frontal = options.frontal;
  }

  RM::Patch_job job(std::size_t p) const
  {
    return RM::patch_job(p, surface.patches, samples, neighbours, *sizing, meshing, RM::Sample_pairs());
  }
};

void expect_same_mesh(const RM::Remeshed_patch& a, const RM::Remeshed_patch& b)
{
  EXPECT_EQ(a.boundary_ids, b.boundary_ids);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.interior_points, b.interior_points);
  EXPECT_EQ(a.interior_faces, b.interior_faces);
  EXPECT_EQ(a.chords_not_glued, b.chords_not_glued);
  EXPECT_EQ(a.sample_diagonals, b.sample_diagonals);
}

} // namespace

TEST(PatchJobs, AJobReadsNothingButItself)
{
  // The jobs outlive the segmentation, the shared samples and the size field they were made
  // from, and give the same meshes as while those lived (under the sanitizers, a job that
  // still read them would fail here).
  std::vector<RM::Patch_job> jobs;
  std::vector<RM::Remeshed_patch> meshed_while_alive;
  {
    const Plate_patches plate;
    ASSERT_GT(plate.surface.patches.size(), 1u);
    for(std::size_t p = 0; p < plate.surface.patches.size(); ++p)
    {
      jobs.push_back(plate.job(p));
      meshed_while_alive.push_back(RM::mesh_patch(jobs.back()));
    }
  }
  std::size_t triangles = 0;
  for(std::size_t p = 0; p < jobs.size(); ++p)
  {
    const RM::Remeshed_patch again = RM::mesh_patch(jobs[p]);
    expect_same_mesh(again, meshed_while_alive[p]);
    EXPECT_TRUE(again.chords_not_glued.empty());
    triangles += again.triangles.size();
  }
  EXPECT_GT(triangles, 1000u);
}

TEST(PatchJobs, AnEqualJobOnRenumberedSamplesHasTheSameMeshRenumbered)
{
  // One curve sampled twice as densely renumbers the samples after it: the patches away from it
  // have equal jobs, whose earlier meshes, renumbered, are what running them again gives; the
  // patches along it do not.
  const Plate_patches coarse;
  std::vector<int> halvings(coarse.samples.number_of_curves, 0);
  halvings[0] = 1;
  const Plate_patches finer(halvings);
  ASSERT_GT(finer.samples.points.size(), coarse.samples.points.size());
  std::size_t equal = 0, different = 0;
  for(std::size_t p = 0; p < coarse.surface.patches.size(); ++p)
  {
    // Both were segmented and flattened separately: give them the same surface to compare.
    RM::Patch_job before = coarse.job(p), after = finer.job(p);
    after.surface = before.surface;
    if(!RM::same_meshing_inputs(before, after))
    {
      ++different;
      continue;
    }
    ++equal;
    EXPECT_NE(before.boundary.number_of_shared_samples, after.boundary.number_of_shared_samples);
    expect_same_mesh(RM::renumbered(RM::mesh_patch(before), before.boundary, after.boundary), RM::mesh_patch(after));
  }
  EXPECT_GT(equal, 0u);
  EXPECT_GT(different, 0u);
}

TEST(PatchJobs, JobsDifferWhenTheirDiagonalsToSplitDo)
{
  const Plate_patches plate;
  const RM::Patch_job job = plate.job(0);
  RM::Patch_job split = job;
  ASSERT_GE(job.boundary.sample_ids.size(), 3u);
  split.diagonals_to_split.insert(std::minmax(job.boundary.sample_ids[0], job.boundary.sample_ids[2]));
  EXPECT_TRUE(RM::same_meshing_inputs(job, job));
  EXPECT_FALSE(RM::same_meshing_inputs(job, split));
  // A diagonal between samples the patch does not have does not change its meshing.
  RM::Patch_job elsewhere = job;
  elsewhere.diagonals_to_split.insert(std::make_pair(plate.samples.points.size() + 1, plate.samples.points.size() + 2));
  EXPECT_TRUE(RM::same_meshing_inputs(job, elsewhere));
}

TEST(PatchJobs, JobsDifferWhereALocalRefinementReachesTheirPatch)
{
  // Meshing again finer near one more place where the output intersected itself changes the
  // jobs of the patches that the smaller sizes reach, even where their boundary samples stay,
  // and only those.
  const Plate_patches plate;
  const double h = plate.sizing->target();
  const auto& m = plate.surface.segmentation.mesh;
  const auto place_in = [&](std::size_t p) {
    return m.point(m.target(m.halfedge(plate.surface.patches[p]->patch.segmented_face.front())));
  };
  ASSERT_GE(plate.surface.patches.size(), 2u);
  RM::Local_refinement one, two;
  one.add({place_in(0)}, h / 4.);
  two.add({place_in(0), place_in(plate.surface.patches.size() - 1)}, h / 4.);
  const RM::Sizing first(plate.surface.segmentation, h, RM::Sizing::Field(), 0., one);
  const RM::Sizing second(plate.surface.segmentation, h, RM::Sizing::Field(), 0., two);
  std::size_t reached = 0, unreached = 0;
  for(std::size_t p = 0; p < plate.surface.patches.size(); ++p)
  {
    RM::Patch_job before = plate.job(p), after = plate.job(p);
    before.size = first.restricted_to(plate.surface.patches[p]->patch);
    after.size = second.restricted_to(plate.surface.patches[p]->patch);
    EXPECT_TRUE(RM::same_meshing_inputs(before, before));
    if(RM::same_meshing_inputs(before, after))
      ++unreached;
    else
      ++reached;
  }
  EXPECT_GE(reached, 1u);   // the patch holding the new place at least
  EXPECT_GE(unreached, 1u); // the plate's patches far from it
  RM::Patch_job uniform = plate.job(0), refined = plate.job(0);
  refined.size = first.restricted_to(plate.surface.patches[0]->patch);
  EXPECT_FALSE(RM::same_meshing_inputs(uniform, refined));
}

namespace {

// A runner that passes every job and result through bytes, as the MPI tool does between
// processes: each job with its surface the first time its patch is seen, without it after.
struct Runner_through_bytes
{
  RM::Patch_surfaces surfaces; // the other process's copies
  std::set<std::size_t> sent;
  std::size_t jobs = 0, jobs_without_surface = 0, bytes = 0;

  void operator()(const std::vector<std::size_t>& to_run, const std::vector<RM::Patch_job>& all,
                  std::vector<RM::Remeshed_patch>& remeshed, std::vector<std::string>& failures)
  {
    for(std::size_t p : to_run)
    {
      const bool with_surface = sent.insert(p).second;
      const std::string job_bytes = RM::write_patch_job(all[p], with_surface);
      bytes += job_bytes.size();
      ++jobs;
      jobs_without_surface += !with_surface;
      const RM::Patch_job job = RM::read_patch_job(job_bytes.data(), job_bytes.size(), surfaces);
      std::string failure;
      RM::Remeshed_patch result;
      try
      {
        result = RM::mesh_patch(job);
      }
      catch(const CR::Error& e)
      {
        failure = e.what();
      }
      const std::string result_bytes = RM::write_patch_result(job.patch, result, failure);
      const std::size_t patch = RM::read_patch_result(result_bytes.data(), result_bytes.size(), remeshed[p], failures[p]);
      EXPECT_EQ(patch, p);
    }
  }
};

} // namespace

TEST(PatchJobs, AJobReadBackFromItsBytesGivesTheSameMesh)
{
  const Plate_patches plate;
  RM::Patch_surfaces surfaces;
  for(std::size_t p = 0; p < plate.surface.patches.size(); ++p)
  {
    const RM::Patch_job job = plate.job(p);
    const std::string bytes = RM::write_patch_job(job, true);
    const RM::Patch_job read = RM::read_patch_job(bytes.data(), bytes.size(), surfaces);
    EXPECT_EQ(read.patch, p);
    EXPECT_TRUE(RM::same_meshing_inputs(read, RM::Patch_job(read))); // a usable job
    EXPECT_EQ(RM::write_patch_job(read, true), bytes);                // nothing lost on the way
    expect_same_mesh(RM::mesh_patch(read), RM::mesh_patch(job));
    // Without its surface, the job takes the one the reader has.
    const std::string light = RM::write_patch_job(job, false);
    EXPECT_LT(light.size(), bytes.size() / 2);
    EXPECT_EQ(RM::read_patch_job(light.data(), light.size(), surfaces).surface, surfaces.at(p));
  }
}

TEST(PatchJobs, BrokenJobBytesAreRefusedWithAnError)
{
  const Plate_patches plate;
  const std::string bytes = RM::write_patch_job(plate.job(0), true);
  RM::Patch_surfaces surfaces;
  for(std::size_t size : {std::size_t(0), std::size_t(5), bytes.size() / 3, bytes.size() - 1})
    EXPECT_THROW(RM::read_patch_job(bytes.data(), size, surfaces), CR::Error) << size;
  const std::string longer = bytes + "x";
  EXPECT_THROW(RM::read_patch_job(longer.data(), longer.size(), surfaces), CR::Error);
  // A job without its surface, sent to a reader that never had it.
  const std::string light = RM::write_patch_job(plate.job(1), false);
  RM::Patch_surfaces none;
  test_support::expect_error([&] { RM::read_patch_job(light.data(), light.size(), none); }, CR::Error_code::INVALID_INPUT,
                             {"comes without its surface"});
  // A user sizing field is a function: it cannot cross processes.
  RM::Patch_job with_field = plate.job(0);
  with_field.size = RM::Patch_size_field(plate.sizing->target(), 0.5, [](const K::Point_3&) { return 1.; },
                                         RM::Local_refinement(), {});
  test_support::expect_error([&] { RM::write_patch_job(with_field, true); }, CR::Error_code::INVALID_INPUT, {"user sizing field"});
}

TEST(PatchJobs, RemeshingWithJobsRunThroughBytesGivesTheSameOutput)
{
  // The MPI tool's contract: the output does not depend on where the jobs run.
  Mesh plate, here, through_bytes;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(std::string(CONFORMAL_REMESHING_EXAMPLE_DATA) + "/perforated_plate.off", plate));
  CR::remesh_conformal<CGAL::Sequential_tag>(plate, here);
  Runner_through_bytes runner;
  const RM::Patch_job_runner run = [&runner](const std::vector<std::size_t>& to_run, const std::vector<RM::Patch_job>& jobs,
                                             std::vector<RM::Remeshed_patch>& remeshed, std::vector<std::string>& failures) {
    runner(to_run, jobs, remeshed, failures);
  };
  CR::remesh_conformal<CGAL::Sequential_tag>(plate, through_bytes, CR::parameters::patch_job_runner(run));
  EXPECT_GE(runner.jobs, 10u); // one per patch at least
  EXPECT_GT(here.number_of_vertices(), 1000u);
  EXPECT_EQ(off_text(through_bytes), off_text(here));
}

TEST(PatchJobs, AFlattenedPatchKeepsItsTipsAndMapsNotItsMesh)
{
  // An open cone of 16 facets (a disc, flattened whole): its apex, a vertex the output would cut,
  // is kept as a tip of the patch. The meshing reads the tips; the patch's mesh is freed once
  // flattened.
  Mesh cone;
  const CGAL::Epick::Point_3 apex(0, 0, 0.5);
  const auto top = cone.add_vertex(apex);
  std::vector<Mesh::Vertex_index> rim;
  for(int i = 0; i < 16; ++i)
    rim.push_back(cone.add_vertex(CGAL::Epick::Point_3(std::cos(i * CGAL_PI / 8.), std::sin(i * CGAL_PI / 8.), 0)));
  for(int i = 0; i < 16; ++i)
    cone.add_face(top, rim[i], rim[(i + 1) % 16]);
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(cone));
  const auto np = CGAL::parameters::default_values();
  const RM::Remeshing_options options = RM::remeshing_options(cone, np);
  CR::Remeshing_report report;
  CR::Remeshing_statistics statistics;
  RM::Flattened_surface surface;
  RM::segment_and_flatten<CGAL::Sequential_tag>(cone, options, np, CR::internal::Time_limit::from(np, "test"),
                                                [](const std::string&) {}, report, statistics, surface);
  std::size_t apexes = 0;
  for(const auto& patch : surface.patches)
  {
    EXPECT_EQ(patch->patch.mesh.number_of_vertices(), 0u);
    EXPECT_FALSE(patch->patch.segmented_face.empty());
    for(const RM::Tip_candidate& tip : patch->tips)
    {
      EXPECT_EQ(surface.segmentation.mesh.point(patch->patch.segmented_vertex.at(tip.vertex)), tip.point);
      apexes += tip.point == apex;
    }
    for(std::size_t i = 1; i < patch->tips.size(); ++i)
      EXPECT_GE(patch->tips[i - 1].cut, patch->tips[i].cut); // the highest first
  }
  EXPECT_EQ(apexes, 1u) << surface.patches.size() << " patches, " << report.plane_cuts << " plane cuts";
}

// Without a visitor, each patch is compacted as soon as it is flattened, and what a round of
// bisections kept is dropped when the next round flattens the patches anew; with a visitor, all
// are compacted once flattened. The patches are the same either way.
TEST(PatchJobs, PatchesCompactedAsTheyAreFlattenedAreThoseCompactedAtTheEnd)
{
  Mesh cap;
  bm::make_spherical_cap(cap, 120., 8, 24);
  const auto flattened = [&](const auto& np, RM::Flattened_surface& surface, CR::Remeshing_report& report,
                             CR::Remeshing_statistics& statistics) {
    RM::segment_and_flatten<CGAL::Sequential_tag>(cap, RM::remeshing_options(cap, np), np, CR::internal::Time_limit::from(np, "test"),
                                                  [](const std::string&) {}, report, statistics, surface);
  };
  RM::Flattened_surface reference, whole, compacted;
  CR::Remeshing_report reference_report, report, visited_report;
  CR::Remeshing_statistics reference_statistics, statistics, visited_statistics;
  flattened(CGAL::parameters::default_values(), reference, reference_report, reference_statistics);
  // A scale ratio below the cap's bisects it: more than one round.
  const double ratio = 0.8 * reference_statistics.max_scale_ratio;
  ASSERT_GT(ratio, 1.);
  std::size_t visits = 0;
  flattened(CR::parameters::maximum_scale_ratio(ratio), compacted, report, statistics);
  flattened(CR::parameters::flattened_patch_visitor(
              [&](const CR::Extracted_patch& patch, const CR::Conformal_flattening&) {
                ++visits;
                EXPECT_GT(patch.mesh.number_of_faces(), 0u); // whole when visited
              },
              CR::parameters::maximum_scale_ratio(ratio)),
            whole, visited_report, visited_statistics);
  EXPECT_GT(report.patch_bisections, 0u);
  EXPECT_EQ(report.patch_bisections, visited_report.patch_bisections);
  ASSERT_EQ(compacted.patches.size(), whole.patches.size());
  EXPECT_EQ(visits, whole.patches.size());
  EXPECT_EQ(statistics.patches.size(), compacted.patches.size()); // the reports of the last round's patches
  for(std::size_t p = 0; p < whole.patches.size(); ++p)
  {
    const RM::Flattened_patch &a = *compacted.patches[p], &b = *whole.patches[p];
    EXPECT_EQ(a.patch.mesh.number_of_vertices(), 0u);
    EXPECT_EQ(b.patch.mesh.number_of_vertices(), 0u);
    EXPECT_EQ(a.patch.segmented_face, b.patch.segmented_face);
    EXPECT_EQ(a.flattening.uv, b.flattening.uv);
    EXPECT_EQ(a.flattening.triangles, b.flattening.triangles);
    EXPECT_EQ(a.scale, b.scale);
    EXPECT_EQ(a.tip_length, b.tip_length);
    ASSERT_EQ(a.tips.size(), b.tips.size());
    for(std::size_t i = 0; i < a.tips.size(); ++i)
      EXPECT_TRUE(a.tips[i].vertex == b.tips[i].vertex && a.tips[i].point == b.tips[i].point && a.tips[i].cut == b.tips[i].cut);
  }
}
