#include "fsi_app/cli.hpp"

#include "fsi/core/error.hpp"
#include "fsi_app/run.hpp"
#include "fsi_app/scene.hpp"
#include "fsi_app/version.hpp"

#include <omp.h>

namespace fsi::app {

namespace {

constexpr const char* kUsage = R"(usage:
  fsi run SCENE --out DIR [--set key.path=value]... [--threads N] [--restart CHECKPOINT]
  fsi check SCENE [--set key.path=value]...
  fsi reference            print the scene-file reference (Markdown)
  fsi --help | --version

run     validates SCENE, then simulates it and writes DIR/fields.h5 (+ fields.xmf for ParaView),
        DIR/probes.csv and DIR/run.json
check   validates SCENE only
--set   overrides one scene entry, e.g. --set time.end=0.1 --set structures[0].material.density=2000
--restart continues from DIR/checkpoint_<step>.h5 (same scene and --out DIR; the output files are
        cut back to the checkpoint and continued); see docs/reliability.md
SIGINT/SIGTERM: the run finishes its step, writes a checkpoint and exits with 130/143
exit status: 0 success, 2 bad input, 3 the run stopped (see its message and run.json), 1 internal,
             130/143 interrupted by SIGINT/SIGTERM (a checkpoint was written)
)";

struct Args {
  std::string command, scene, out, restart;
  std::vector<std::string> overrides;
  int threads = 0;
};

Args parse(const std::vector<std::string>& args) {
  Args a;
  if (args.empty()) throw InputError("fsi: missing command (see fsi --help)");
  a.command = args[0];
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& arg = args[i];
    auto value = [&](const std::string& name) {
      if (i + 1 >= args.size()) throw InputError("fsi: " + name + " needs a value");
      return args[++i];
    };
    if (arg == "--set") {
      a.overrides.push_back(value(arg));
    } else if (arg.rfind("--set=", 0) == 0) {
      a.overrides.push_back(arg.substr(6));
    } else if (arg == "--out") {
      a.out = value(arg);
    } else if (arg == "--restart") {
      a.restart = value(arg);
    } else if (arg == "--threads") {
      const std::string v = value(arg);
      try {
        std::size_t used = 0;
        a.threads = std::stoi(v, &used);
        if (used != v.size() || a.threads < 1) throw std::invalid_argument(v);
      } catch (const std::exception&) {
        throw InputError("fsi: --threads: expected a positive integer, got '" + v + "'");
      }
    } else if (arg.rfind("-", 0) == 0) {
      throw InputError("fsi: unknown option '" + arg + "' (see fsi --help)");
    } else if (a.scene.empty()) {
      a.scene = arg;
    } else {
      throw InputError("fsi: unexpected argument '" + arg + "'");
    }
  }
  return a;
}

int dispatch(const Args& a, std::ostream& out, std::ostream& err, bool terminal) {
  if (a.command == "reference") {
    out << scene_reference();
    return 0;
  }
  if (a.command != "run" && a.command != "check")
    throw InputError("fsi: unknown command '" + a.command + "' (see fsi --help)");
  if (a.scene.empty()) throw InputError("fsi " + a.command + ": missing SCENE");
  if (a.command == "run" && a.out.empty()) throw InputError("fsi run: missing --out DIR");
  const Scene scene = load_scene(a.scene, a.overrides);
  auto models = build_models(scene);
  if (a.command == "check") {
    out << a.scene << ": ok\n";
    return 0;
  }
  if (!a.restart.empty() && a.command != "run")
    throw InputError("fsi " + a.command + ": --restart is for fsi run");
  if (a.threads > 0) omp_set_num_threads(a.threads);
  const RunResult result = run_scene(scene, models, {a.out, terminal, &err, a.restart});
  if (result.signal != 0) {
    err << "interrupted by signal " << result.signal << " at step " << result.step
        << ", t = " << result.time << " s; continue with: fsi run " << a.scene << " --out " << a.out
        << " --restart " << result.checkpoint.string() << '\n';
    return 128 + result.signal;
  }
  out << "results: " << a.out << "/fields.xmf (ParaView), " << a.out << "/probes.csv, " << a.out
      << "/run.json\n";
  return 0;
}

} // namespace

int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
            bool terminal) {
  if (!args.empty() && (args[0] == "--help" || args[0] == "-h" || args[0] == "help")) {
    out << kUsage;
    return 0;
  }
  if (!args.empty() && args[0] == "--version") {
    out << "fsi " << version() << " (" << git_revision() << ")\n";
    return 0;
  }
  try {
    return dispatch(parse(args), out, err, terminal);
  } catch (const InputError& e) {
    err << e.what() << '\n';
    return 2;
  } catch (const RunError& e) {
    err << "run stopped: " << e.what() << '\n';
    return 3;
  } catch (const std::exception& e) {
    err << "internal error: " << e.what() << '\n';
    return 1;
  }
}

} // namespace fsi::app
