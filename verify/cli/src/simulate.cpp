// fdhcert simulate: one scene, frame by frame, timed and checked.
#include <nlohmann/json.hpp>

#include <memory>
#include <optional>

#include "commands.hpp"
#include "fdh/io/query_io.hpp"
#include "fdh/io/scene_schema.hpp"
#include "fdh/scene/simulate_job.hpp"

namespace fdh::verify {
namespace {

const char* const kSimulateAbout =
    R"(run a cloth scene: time per frame, accuracy and exact audit

Runs the cloth of SCENE (a .scene file, docs/formats.md; shipped ones are in
corpus/scenes/) among its obstacles, one step of dt per frame: springs and
Euler integration (eqs. 1-3), refit of the cloth's FDH tree with swept leaves,
traversal against the obstacles' tree, the narrow-phase test on every
candidate pair, and the response of eqs. 4-5.

Prints the mean time per frame split into those five parts, the candidate
pairs and collisions, and two checks, both untimed:
  accuracy  every narrow-phase query against the exact point-triangle test
            (false positives and false negatives);
  audit     after every frame (or the scene's audit_every-th and the last),
            the exact count of cloth particles strictly inside an
            obstacle and of cloth triangles meeting an obstacle
            triangle (touching counts), summed over the frames: the
            engine of `fdhcert audit`, each frame on its own.
And the gaps kept: the skin (thickness) and, with self_collision on, the
self distance the cloth keeps from itself (scene key self_distance, by
default the skin), each with the smallest distance reached at the end of a
frame (float measures, not certificates).)";

const char* const kSimulateFooter =
    R"(If the scene's dt is above the cloth's stable step (it shrinks as the grid
grows), 0.9 times the stable step is used, and the output says so.
Exit status: 0; 2 for bad input. A scene error names the file and line.)";

// The job's options (fdh/scene/simulate_job.hpp) and what only the command line has.
struct SimulateCli {
  SimulateOptions job;
  bool json = false, no_check = false;
  ProgressWhen progress = ProgressWhen::Auto;
};

int run_simulate(SimulateCli& o, const Io& io) {
  o.job.run.check = !o.no_check;
  ProgressLine progress(io.err, progress_wanted(io, o.progress));
  o.job.progress = progress.sink();
  const SimulateResult r = simulate_job(o.job);
  progress.clear();
  if (o.json)
    print_json(io.out, r.to_json());
  else
    io.out << r.text();
  return 0;
}

// An override of a scene value (--grid, --frames, --thickness): a number, read as query files
// read numbers, within the value's range in the scene schema (fdh/io/scene_schema.hpp), with
// the scene reader's words.
CLI::Validator scene_value_validator(const char* field) {
  return CLI::Validator(
      [field](std::string& s) -> std::string {
        const SceneValue& f = scene_value(field);
        std::string why;
        const std::optional<double> v = parse_double(s, why);
        if (!v) return why;
        return f.admits(*v) ? "" : f.refusal(field, quoted_input(s), *v);
      },
      "");
}

void add_scene_options(CLI::App& cmd, SimulateOptions& o) {
  cmd.add_option("SCENE", o.scene_path, "a .scene file (corpus/scenes/)")->required();
  cmd.add_option("--grid", o.overrides.grid, "particles per side (default: the scene's)")
      ->type_name("N")
      ->check(scene_value_validator("grid"));
  cmd.add_option("--frames", o.run.frames, "frames to run (default: the scene's)")
      ->type_name("F")
      ->check(scene_value_validator("frames"));
  cmd.add_option("--narrow", o.run.narrow,
                 "robust (default), exact, paper-intended, paper-literal or\nlinear-system")
      ->type_name("METHOD")
      ->check(one_of(narrow_phase_names()));
  cmd.add_option("--k", o.run.k, "the FDH's k: 6, 14, 18 (default) or 26")
      ->type_name("K")
      ->check(kdop_k_validator(false));
  cmd.add_option("--thickness", o.overrides.thickness,
                 "the collision skin in m (default: the scene's; 0 collides\n"
                 "with the obstacles' own surfaces, see docs/cloth.md)")
      ->type_name("T")
      ->check(scene_value_validator("thickness"));
  cmd.add_option("--self", o.overrides.self,
                 "the cloth against itself: moving vertex-face and edge-edge\n"
                 "tests with robust CCD among primitives sharing no particle\n"
                 "(default: the scene's self_collision, else off)")
      ->type_name("on|off")
      ->check(one_of({"on", "off"}));
  cmd.add_flag("--audit-self", o.run.audit_self,
               "count self-crossings (cloth triangles meeting cloth triangles\n"
               "that share no particle) even without the self-collision pass");
}

void add_output_options(CLI::App& cmd, SimulateCli& c) {
  SimulateOptions& o = c.job;
  cmd.add_option("--obj", o.files.obj_dir,
                 "write DIR/frame_NNNNN.obj for every frame, from 00000 (the\n"
                 "initial state), with objects cloth and obstacles, for\n"
                 "`fdhcert audit`, Blender or ParaView")
      ->type_name("DIR");
  cmd.add_option("--png", o.files.png, "render the last frame to FILE")->type_name("FILE");
  cmd.add_option("--movie", o.files.movie,
                 "render the run to FILE as an animated PNG (APNG, 400x300,\n"
                 "16 frames per second, looping; browsers play it)")
      ->type_name("FILE");
  add_number_option(cmd, "--movie-frames", o.files.movie_frames,
                    "about how many frames the movie shows, evenly spread\n"
                    "over the run (default 48)",
                    "N", 1, 10000);
  cmd.add_option("--record", o.files.record,
                 "write every narrow-phase query of the run to FILE in the\n"
                 "native vf format, for `fdhcert classify FILE`")
      ->type_name("FILE");
  add_threads_option(cmd, o.threads, "the step");
  cmd.add_flag("--json", c.json, "print one JSON object instead of the text");
  cmd.add_flag("--no-check", c.no_check, "skip the accuracy count and the audit");
  add_quiet_flag(cmd, c.progress);
}

}  // namespace

Command add_simulate(CLI::App& app) {
  auto o = std::make_shared<SimulateCli>();
  CLI::App* cmd = add_command(app, "simulate", kSimulateAbout, kSimulateFooter);
  add_scene_options(*cmd, o->job);
  add_output_options(*cmd, *o);
  return {cmd, [o](const Io& io) { return run_simulate(*o, io); }};
}

}  // namespace fdh::verify
