#include "fsi_app/cli.hpp"

#include "fsi/core/error.hpp"
#include "fsi/core/parallel.hpp"
#include "fsi_app/run.hpp"
#include "fsi_app/scene.hpp"
#include "fsi_app/scene_reader.hpp"
#include "fsi_app/version.hpp"
#include "fsi_app/wall_motion.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace fsi::app {

namespace {

constexpr const char* kUsage = R"(usage:
  fsi run SCENE --out DIR [--set key.path=value]... [--threads N] [--restart CHECKPOINT]
          [--overwrite]
  fsi check SCENE [--set key.path=value]...
  fsi reference            print the scene-file reference (Markdown)
  fsi --help | --version

run     validates SCENE, then simulates it and writes DIR/fields.h5 (+ fields.xmf for ParaView),
        DIR/probes.csv and DIR/run.json
check   validates SCENE only
--set   overrides one scene entry, e.g. --set time.end=0.1 --set structures[0].material.density=2000
--restart continues from DIR/checkpoint_<step>.h5 (same scene and --out DIR; the output files are
        cut back to the checkpoint and continued; give the run's --set overrides again);
        see docs/reliability.md
--overwrite deletes the files of an earlier run in DIR first (fields.h5, fields.xmf, probes.csv,
        run.json, coupling.csv, interface.h5, checkpoint_*.h5, failed_state.h5); without it
        such a folder is refused. One run at a time per DIR (DIR/.lock).
--threads the most threads, at most the processors this process may use; each step runs on the
        count its measured time favours (fewer when a core is shared; output: bitwise the same
        for any count, docs/reliability.md)
SIGINT/SIGTERM: the run finishes its step, writes a checkpoint and exits with 130/143
exit status: 0 success, 2 bad input, 3 the run stopped (see its message and run.json), 1 internal,
             130/143 interrupted by SIGINT/SIGTERM (a checkpoint was written)
)";

struct Args {
  std::string command, scene, out, restart;
  std::vector<std::string> overrides;
  int threads = 0;
  bool overwrite = false, help = false;
};

/// `word` quoted for a POSIX shell when it holds anything but safe characters.
std::string shell_word(const std::string& word) {
  const bool safe = !word.empty() && std::all_of(word.begin(), word.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) ||
           std::string("_-+=.,/:@%[]").find(c) != std::string::npos;
  });
  if (safe) return word;
  std::string out = "'";
  for (const char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

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
    if (arg == "--help" || arg == "-h") {
      a.help = true;
    } else if (arg == "--overwrite") {
      a.overwrite = true;
    } else if (arg == "--set") {
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

/// Under mpirun: what the decomposed run does not support yet (issue 47), refused before any
/// computation; nothing otherwise.
void check_decomposable(const Scene& scene, const Args& a, const Ranks& ranks) {
  if (!ranks.decomposed()) return;
  auto refuse = [&](const std::string& what) {
    throw InputError(a.scene + ": not yet supported under mpirun (" + std::to_string(ranks.size()) +
                     " processes, issue 47): " + what + "; run it without mpirun");
  };
  if (!scene.fluid || (scene.fluid->type != "emps" && scene.fluid->type != "sph"))
    refuse(scene.fluid ? "fluid.type " + scene.fluid->type + " (EMPS and SPH only)"
                       : "a scene without fluid");
}

int dispatch(const Args& a, std::ostream& out, std::ostream& err, bool terminal,
             const Ranks& ranks) {
  if (a.command != "run" && a.command != "check" && a.command != "reference")
    throw InputError("fsi: unknown command '" + a.command + "' (see fsi --help)");
  if (a.help) {
    out << kUsage;
    return 0;
  }
  if (a.command == "reference") {
    if (!a.scene.empty() || !a.overrides.empty() || !a.out.empty() || !a.restart.empty() ||
        a.threads || a.overwrite)
      throw InputError("fsi reference: takes no arguments");
    out << scene_reference();
    return 0;
  }
  if (a.command == "check") {
    for (const auto& [given, name] : {std::pair{!a.out.empty(), "--out"},
                                      {!a.restart.empty(), "--restart"},
                                      {a.threads > 0, "--threads"},
                                      {a.overwrite, "--overwrite"}})
      if (given) throw InputError(std::string("fsi check: ") + name + " is for fsi run");
  }
  if (a.scene.empty()) throw InputError("fsi " + a.command + ": missing SCENE");
  if (a.command == "run" && a.out.empty()) throw InputError("fsi run: missing --out DIR");
  if (a.overwrite && !a.restart.empty())
    throw InputError("fsi run: --overwrite starts afresh, --restart continues: give one of them");
  const int processors = available_processors();
  if (a.threads > processors)
    throw InputError("fsi: --threads " + std::to_string(a.threads) + ": this machine has " +
                     std::to_string(processors) + " processor" + (processors == 1 ? "" : "s") +
                     " for this process; give at most " + std::to_string(processors));
  const Scene scene = load_scene(a.scene, a.overrides);
  check_motion_tables(scene);
  // Errors from the libraries (a mesher's "duplicate node") name no file: give them the scene's.
  auto named = [&](auto&& build) {
    try {
      return build();
    } catch (const InputError& e) {
      const std::string what = e.what();
      if (what.find(a.scene) != std::string::npos) throw;
      throw InputError(a.scene + ": " + what);
    }
  };
  if (a.command == "check") {
    named([&] { check_models(scene); });
    out << a.scene << ": ok\n";
    return 0;
  }
  check_decomposable(scene, a, ranks);
  auto models = named([&] { return build_models(scene, ranks); }); // decomposed by run_scene
  if (a.threads > 0) set_num_threads(a.threads);
  RunOptions options{a.out, terminal, &err, a.restart};
  options.overwrite = a.overwrite;
  options.ranks = &ranks;
  const RunResult result = run_scene(scene, models, options);
  if (result.signal != 0) {
    // The command that continues it: the same scene, overrides and threads (and processes:
    // any count continues it, docs/reliability.md).
    std::string again = "fsi run " + shell_word(a.scene) + " --out " + shell_word(a.out);
    if (ranks.decomposed()) again = "mpirun -np " + std::to_string(ranks.size()) + " " + again;
    for (const auto& o : a.overrides) again += " --set " + shell_word(o);
    if (a.threads > 0) again += " --threads " + std::to_string(a.threads);
    again += " --restart " + shell_word(result.checkpoint.string());
    err << "interrupted by signal " << result.signal << " at step " << result.step
        << ", t = " << result.time << " s; continue with: " << again << '\n';
    return 128 + result.signal;
  }
  out << "results: " << a.out << "/fields.xmf (ParaView), " << a.out << "/probes.csv, " << a.out
      << "/run.json\n";
  return 0;
}

} // namespace

int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
            bool terminal, const Ranks& ranks) {
  if (!args.empty() && (args[0] == "--help" || args[0] == "-h" || args[0] == "help")) {
    out << kUsage;
    return 0;
  }
  if (!args.empty() && args[0] == "--version") {
    out << "fsi " << version() << " (" << git_revision() << ")\n";
    return 0;
  }
  try {
    return dispatch(parse(args), out, err, terminal, ranks);
  } catch (const InputError& e) {
    err << e.what() << '\n';
    return 2;
  } catch (const RunError& e) {
    err << "run stopped: " << e.what() << '\n';
    return 3;
  } catch (const std::filesystem::filesystem_error& e) {
    // A folder or file the user named that cannot be used (permissions, a full disk).
    err << "fsi: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    err << "internal error: " << e.what() << '\n';
    return 1;
  }
}

} // namespace fsi::app
