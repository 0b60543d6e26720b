// The run of one sweep (output/sweep_run.hpp) that the command line and the Python module share: the same
// request gives the poses of a direct assemble() + sweep() to the last bit, its files are the table's bytes,
// and everything it refuses (an output naming an input, a missing or bad sweep, work above the bound) is
// refused when the run is made, before anything is solved, naming the caller's options.
#define BOOST_TEST_MODULE output_sweep_run
#include <boost/test/unit_test.hpp>

#include "test_support.hpp"

#include "rollkin/io/output_set.hpp"
#include "rollkin/io/scene/reader.hpp"
#include "rollkin/output/sweep_file.hpp"
#include "rollkin/output/sweep_table.hpp"
#include "rollkin/output/sweep_run.hpp"
#include "rollkin/solve/continuation.hpp"
#include "rollkin/solve/position.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <vector>

using namespace rollkin;
namespace fs = std::filesystem;

namespace {

const std::string kExamples = std::string(ROLLKIN_SOURCE_DIR) + "/examples/";
const output::RequestNames kNames{"--from/--to/--step", "--from, --to and --step", "--max-steps"};

std::shared_ptr<const io::Scene> scene_of(const std::string& file) {
  return std::make_shared<const io::Scene>(io::load_scene(file));
}

/// The files a scene read, as the command line names them.
std::vector<io::InputFile> inputs_of(const io::Scene& scene) {
  std::vector<io::InputFile> inputs{{scene.file, ""}};
  for (const std::string& f : scene.files_read) inputs.push_back({f, ""});
  return inputs;
}

/// The paper example from -50 to 130 degrees by 0.5, past its dead point (a limit, then rows not reached).
output::SweepRequest past_the_dead_point() {
  output::SweepRequest r;
  r.to = 130;
  r.step = 0.5;
  r.to_text = "130";
  r.step_text = "0.5";
  return r;
}

/// The message of the exception of type E that `f()` throws ("" if it throws none).
template <class E, class F> std::string error_of(F&& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// The run's sweep against the library called directly on the same scene, inputs and guess: every pose's
// status, variables, rates and residual the same double, and the table's input column the file's grid.
BOOST_AUTO_TEST_CASE(a_run_solves_the_poses_of_a_direct_assembly_and_sweep) {
  const auto scene = scene_of(kExamples + "paper_fourbar.json");
  output::SweepRun run(scene, inputs_of(*scene), {}, past_the_dead_point(), kNames);
  BOOST_TEST(run.sweep().to_text == "130");
  BOOST_TEST(run.sweep().step_text == "0.5");
  BOOST_TEST_REQUIRE(run.inputs().size() == 361u);

  Sweep sw = *scene->sweep;  // the same sweep built by hand
  sw.to = 130;
  sw.step = 0.5;
  const std::vector<double> inputs = sweep_inputs(sw);
  BOOST_TEST(run.inputs() == inputs);
  BOOST_TEST(run.values() == sweep_values(sw));
  const Mechanism<double>& m = scene->mechanism;
  SolveData<double> sd_direct(m);
  VectorX<double> q_direct = scene->guess;
  const SolveReport<double> assembly_direct = assemble(m, q_direct, sd_direct, scene->held);
  const SweepResult<double> direct = sweep(m, sd_direct, q_direct, assembly_direct, sw.driver, inputs);

  SolveData<double> sd(m);
  VectorX<double> q;
  const SolveReport<double> assembly = run.assemble(sd, q);
  BOOST_TEST((q == q_direct));
  BOOST_TEST(assembly.residual == assembly_direct.residual);
  const SweepResult<double> result = run.solve(sd, q, assembly);
  BOOST_TEST_REQUIRE(result.size() == direct.size());
  BOOST_TEST_REQUIRE(direct.limits.size() == 1u);  // the dead point: the comparison covers a limit
  BOOST_TEST(result.limits.size() == 1u);
  std::size_t with_values = 0;
  for (std::size_t k = 0; k < result.size(); ++k) {
    BOOST_TEST((result.status(k) == direct.status(k)), "pose " << k);
    if (!direct.has_pose(k)) continue;
    ++with_values;
    BOOST_TEST((result.q(k) == direct.q(k)), "pose " << k);
    BOOST_TEST((result.qdot(k) == direct.qdot(k)), "pose " << k);
    BOOST_TEST(result.report(k).residual == direct.report(k).residual, "pose " << k);
  }
  BOOST_TEST(with_values > 200u);
  BOOST_TEST(with_values < result.size());  // rows not reached beyond the limit

  // The summary and the poses kept in a file: the same statuses.
  SolveData<double> sd2(m);
  VectorX<double> q2;
  const SolveReport<double> assembly2 = run.assemble(sd2, q2);
  const SweepSummary<double> summary = run.summary(sd2, q2, assembly2);
  BOOST_TEST((summary.status == summarise(direct).status));
  SolveData<double> sd3(m);
  VectorX<double> q3;
  const SolveReport<double> assembly3 = run.assemble(sd3, q3);
  io::SweepFile file(assembly3, run.inputs(), m.variable_count());
  run.solve_into(sd3, q3, assembly3, file);
  BOOST_TEST((file.status == summarise(direct).status));
}

// Files of the sweep formats are written by write() from the solved rows, all at once: the CSV is the bytes of
// the table of a direct sweep (io::sweep_table), whether the rows are in memory or in a file.
BOOST_AUTO_TEST_CASE(a_run_writes_the_table_of_the_direct_sweep) {
  const fs::path dir = testing::scratch_dir("output_sweep_run_write");
  const auto scene = scene_of(kExamples + "paper_fourbar.json");
  const Mechanism<double>& m = scene->mechanism;
  for (const bool in_file : {false, true}) {
    const fs::path csv = dir / (in_file ? "file.csv" : "memory.csv");
    fs::remove(csv);
    output::SweepRun run(scene, inputs_of(*scene), {{"--csv", csv.string(), "csv"}, {"--plot", "", "plot"}},
                         past_the_dead_point(), kNames);
    BOOST_TEST(run.writes_files());
    SolveData<double> sd(m);
    VectorX<double> q;
    const SolveReport<double> assembly = run.assemble(sd, q);
    if (in_file) {
      io::SweepFile rows(assembly, run.inputs(), m.variable_count());
      run.solve_into(sd, q, assembly, rows);
      run.write(run.output(rows), output::WriteOptions{true, 1});
    } else {
      const SweepResult<double> rows = run.solve(sd, q, assembly);
      run.write(run.output(rows), output::WriteOptions{true, 1});
    }
    BOOST_TEST(!fs::exists(dir / "plot"));  // not asked for (path "")

    SolveData<double> sd_direct(m);
    VectorX<double> q_direct = scene->guess;
    const SolveReport<double> assembly_direct = assemble(m, q_direct, sd_direct, scene->held);
    const SweepResult<double> direct = sweep(m, sd_direct, q_direct, assembly_direct, run.sweep().driver, run.inputs());
    const std::vector<double> values = sweep_values(run.sweep());
    const io::SweepOutput out{*scene, run.sweep(), direct, values};
    BOOST_TEST((testing::read_text(csv) == io::sweep_table(out, true).csv()), (in_file ? "rows in a file" : "rows in memory"));
  }
  BOOST_TEST(testing::no_temporaries_in(dir));
}

// An output that is one of the files the run reads (the scene file, a contour file it read) is refused when
// the run is made, before the sweep is even built: the sweep asked for here is also wrong and is not what
// is reported, the file is not touched, and nothing else is written.
BOOST_AUTO_TEST_CASE(an_output_naming_an_input_is_refused_before_solving) {
  const fs::path dir = testing::scratch_dir("output_sweep_run_inputs");
  const fs::path copy = dir / "paper.json";
  fs::copy_file(kExamples + "paper_fourbar.json", copy, fs::copy_options::overwrite_existing);
  const std::string original = testing::read_text(copy);
  const auto scene = scene_of(copy.string());
  output::SweepRequest bad_step;
  bad_step.step = 0;  // not a sweep: would be a SweepRequestError if the outputs passed
  const fs::path other = dir / "other.csv";
  fs::remove(other);
  for (const std::string& format : {std::string("csv"), std::string()}) {
    const std::string message = error_of<io::OutputError>([&] {
      output::SweepRun run(scene, inputs_of(*scene), {{"--plot", other.string(), "plot"}, {"--csv", copy.string(), format}},
                           bad_step, kNames);
    });
    BOOST_TEST(testing::contains(message, "--csv"), "format '" << format << "'");
    BOOST_TEST(testing::contains(message, "paper.json"), "format '" << format << "'");
  }
  BOOST_TEST(testing::read_text(copy) == original);
  BOOST_TEST(!fs::exists(other));
  BOOST_TEST(testing::no_temporaries_in(dir));

  // A contour file the scene read (the DXF of the cam example) is an input as well.
  const auto cam = scene_of(kExamples + "dxf_cam.json");
  BOOST_TEST_REQUIRE(cam->files_read.size() == 1u);
  const std::string message = error_of<io::OutputError>([&] {
    output::SweepRun run(cam, inputs_of(*cam), {{"--out", cam->files_read.front(), ""}}, {}, kNames);
  });
  BOOST_TEST(testing::contains(message, "cam_profile.dxf"));
}

// What the request cannot be run as is refused in the caller's words: no "sweep" in the scene and no range,
// a range that is not a sweep, more values than the bound.
BOOST_AUTO_TEST_CASE(a_request_that_cannot_be_run_names_the_callers_options) {
  nlohmann::ordered_json doc = io::read_scene_document(kExamples + "paper_fourbar.json");
  doc.erase("sweep");
  const auto no_sweep = std::make_shared<const io::Scene>(io::build_scene(doc, "no_sweep.json", kExamples));
  const output::RequestNames python{"start/stop/step", "start, stop and step", "max_steps"};
  BOOST_TEST(testing::contains(error_of<output::SweepRequestError>([&] {
                                 output::SweepRun run(no_sweep, {}, {}, {}, python);
                               }),
                               "no_sweep.json has no \"sweep\"; give start, stop and step"));
  output::SweepRequest range;
  range.from = -50;
  range.to = 100;
  range.step = 5;
  BOOST_TEST(output::SweepRun(no_sweep, {}, {}, range, python).inputs().size() == 31u);

  const auto paper = scene_of(kExamples + "paper_fourbar.json");
  output::SweepRequest zero_step;
  zero_step.step = 0;
  BOOST_TEST(testing::contains(error_of<output::SweepRequestError>([&] {
                                 output::SweepRun run(paper, {}, {}, zero_step, kNames);
                               }),
                               "--from/--to/--step: "));
  output::SweepRequest bounded;  // the paper's 151 values, above a bound of 150
  bounded.max_steps = 150;
  const std::string limit = error_of<io::WorkLimitError>([&] { output::SweepRun run(paper, {}, {}, bounded, python); });
  BOOST_TEST(testing::contains(limit, "has 1.51e+02 values, above the limit 1.50e+02 (max_steps)"));
}

// A scene whose mechanism cannot be assembled: an InputError from assemble(), the report as it is from
// try_assemble() (a batch goes on with its other scenes).
BOOST_AUTO_TEST_CASE(an_assembly_that_fails_is_an_input_error_or_a_report) {
  nlohmann::ordered_json doc = io::read_scene_document(kExamples + "paper_fourbar.json");
  doc["pairs"][3]["at"][0]["x"] = 100;  // O_B far beyond the reach of disk 4: no loop can close
  const auto far = std::make_shared<const io::Scene>(io::build_scene(doc, "far.json", kExamples));
  output::SweepRun run(far, {}, {}, {}, kNames);
  SolveData<double> sd(far->mechanism);
  VectorX<double> q;
  BOOST_TEST(run.try_assemble(sd, q).status == SolveStatus::CannotAssemble);
  const std::string message = testing::input_error_of([&] { run.assemble(sd, q); });
  BOOST_TEST(testing::contains(message, "far.json"));
  BOOST_TEST(testing::contains(message, "the mechanism cannot be assembled"));
}

// A run that keeps the link poses (solve(..., link_poses = true): what the Python module's tables read)
// against one that does not (the table evaluates the tree's pairs at every pose), on the own sweep of every
// example scene that assembles: the same poses, statuses and residuals; the kept link poses within round-off of a fresh
// evaluation at each pose's values (link_poses_at); the tables the same columns, each value equal, the link
// pose columns to round-off (the kept angles are summed down the tree, the evaluated ones atan2 of the rotation).
BOOST_AUTO_TEST_CASE(kept_link_poses_give_the_table_of_a_fresh_evaluation_on_every_example) {
  const double eps = std::numeric_limits<double>::epsilon();
  int scenes = 0;
  for (const auto& file : fs::directory_iterator(kExamples)) {
    if (file.path().extension() != ".json") continue;
    BOOST_TEST_CONTEXT(file.path().filename().string()) {
      const auto scene = scene_of(file.path().string());
      const Mechanism<double>& m = scene->mechanism;
      output::SweepRun run(scene, inputs_of(*scene), {}, {}, kNames);
      SolveData<double> sd(m);
      VectorX<double> q;
      const SolveReport<double> assembly = run.try_assemble(sd, q);
      if (!assembly.ok()) continue;  // (the osculating example: no pose to keep)
      const SweepResult<double> kept = run.solve(sd, q, assembly, nullptr, true);
      SolveData<double> sd2(m);
      VectorX<double> q2;
      const SolveReport<double> assembly2 = run.try_assemble(sd2, q2);
      const SweepResult<double> plain = run.solve(sd2, q2, assembly2, nullptr, false);
      BOOST_TEST_REQUIRE(kept.keeps_link_poses());
      BOOST_TEST(!plain.keeps_link_poses());
      std::vector<SE2<double>> fresh(m.links.size());
      double worst = 0;
      int with_values = 0;
      for (std::size_t k = 0; k < kept.size(); ++k) {
        BOOST_TEST_REQUIRE((kept.status(k) == plain.status(k)));
        BOOST_TEST((kept.q(k) == plain.q(k)));
        if (!kept.has_pose(k)) {
          BOOST_TEST((kept.link_poses(k) == nullptr && kept.link_angles(k) == nullptr));
          continue;
        }
        ++with_values;
        link_poses_at(m, VectorX<double>(kept.q(k)), fresh);
        const SE2<double>* got = kept.link_poses(k);
        const double* angle = kept.link_angles(k);
        worst = std::max(worst, testing::link_pose_difference(got, fresh.data(), fresh.size(), m.length_scale));
        for (std::size_t i = 0; i < fresh.size(); ++i) worst = std::max(worst, testing::angle_gap(angle[i], fresh[i].angle()));
      }
      BOOST_TEST(with_values > 0);
      BOOST_TEST(worst <= 16 * eps);
      const io::SweepColumns a = io::sweep_columns(run.output(kept), true), b = io::sweep_columns(run.output(plain), true);
      BOOST_TEST_REQUIRE((a.names == b.names));
      for (std::size_t c = 0; c < a.names.size(); ++c) {
        const std::string& name = a.names[c];
        bool pose_column = false;
        for (const Link& l : m.links)
          pose_column = pose_column || name == l.name + ".x" || name == l.name + ".y" || name == l.name + ".angle";
        for (std::size_t r = 0; r < a.rows(); ++r) {
          const double x = a.column(c)[r], y = b.column(c)[r];
          if (std::isnan(y)) {
            BOOST_TEST(std::isnan(x), name << " row " << r);
          } else if (pose_column) {  // degrees for an angle; lengths in the scene's size
            BOOST_TEST(std::abs(x - y) <= 64 * eps * std::max(m.length_scale, 180.0), name << " row " << r);
          } else {
            BOOST_TEST(x == y, name << " row " << r);
          }
        }
      }
      ++scenes;
    }
  }
  BOOST_TEST(scenes >= 7);
}
