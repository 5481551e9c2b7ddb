// cambrian audit: checks the physics on many bodies — a passive body at rest stays at rest, and
// no body gains energy that gravity and its effectors do not explain (physics/physics_audit.hpp).
#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"
#include "cambrian/evaluate.hpp"

#include "commands.hpp"
#include "options.hpp"
#include "physics/physics_audit.hpp"
#include "physics/physics_settings.hpp"
#include "store/history.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>

namespace cambrian {

namespace {

// a body to audit and where it came from
struct Candidate {
  std::string source;
  Genotype genome;
};

// the `top` best distinct genomes with status ok of a history (ties: lowest id)
std::vector<Candidate> bestOfHistory(const std::string& path, std::size_t top) {
  HistoryReader history(path);
  std::vector<Individual> rows = history.individuals();
  std::stable_sort(rows.begin(), rows.end(), [](const Individual& a, const Individual& b) {
    return a.fitness() > b.fitness() || (a.fitness() == b.fitness() && a.id < b.id);
  });
  std::vector<Candidate> best;
  std::set<std::vector<std::uint8_t>> seen;
  for (const Individual& row : rows) {
    if (best.size() >= top)
      break;
    if (row.outcome.status != EvalStatus::ok || !seen.insert(row.genome.bytes()).second)
      continue;
    best.push_back({path + " id " + std::to_string(row.id), row.genome});
  }
  return best;
}

// writes a broken body's genome to `dir` as <source>.genome (spaces and slashes as _)
void saveBroken(const std::string& dir, const Candidate& candidate) {
  std::string name = candidate.source;
  for (char& c : name) {
    if (c == ' ' || c == '/')
      c = '_';
  }
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error)
    throw Error(ExitCode::output_file, "--save-broken " + dir + ": " + error.message());
  writeGenomeFile(dir + "/" + name + ".genome", candidate.genome);
}

// order statistics of a list of values
struct Spread {
  std::vector<double> values;
  double at(double fraction) {
    if (values.empty())
      return 0;
    std::sort(values.begin(), values.end());
    auto index = static_cast<std::size_t>(fraction * static_cast<double>(values.size() - 1));
    return values[index];
  }
};

}  // namespace

int runAudit(int argc, char** argv) {
  CreatureSettings settings;
  SettingsSchema schema;
  settings.declareSettings(schema);
  AuditSettings audit;
  std::string config_path, seed_text = "1", tsv_path, broken_dir;
  std::vector<std::string> genome_paths, history_paths;
  std::size_t random = 100, top = 10;
  double max_creep = 0.001, max_passive_gain = 0.05;

  po::options_description cli(
      "cambrian audit: check the physics on many bodies. Each body is run passive (controller\n"
      "off) until every part has been slower than --rest-speed for --rest-window s, then watched\n"
      "for --measure s: a body at rest must stay at rest (its centre of mass moves at most\n"
      "--max-creep, unless it then moves less than half as far over the next --measure s: a real\n"
      "motion dying out under damping and friction, such as a part turning freely about a\n"
      "vertical joint). Its mechanical energy must never rise by more than --max-passive-gain x "
      "its\n"
      "weight x its length over what gravity explains. Then it runs --driven s with its\n"
      "controller on, and the energy its effectors cannot have supplied is reported\n"
      "(physics.max_energy_gain ends such a run as exploded). Bodies: --random N genomes of the\n"
      "encoding, --genome files, the --top best of --history runs (their genomes only: the\n"
      "settings are this command's).\n\n"
      "usage: cambrian audit [--random N] [--seed S] [--genome FILE]... [--history FILE [--top "
      "K]]...\n"
      "                      [--config FILE] [--tsv FILE] [settings]\n"
      "Exit codes: 0 every check holds, 11 a body broke one (listed), 2 bad command line, 3 bad\n"
      "setting, 4 unreadable genome or history, 5 --tsv cannot be written.\n\n"
      "Options");
  cli.add_options()("help,h", "show this help")("random", po::value(&random)->default_value(random),
                                                "random genomes to audit")(
      "seed", po::value(&seed_text)->default_value(seed_text), "seed of the random genomes")(
      "genome,g", po::value(&genome_paths), "a genome file to audit (repeatable)")(
      "history", po::value(&history_paths), "audit the best genomes of this history (repeatable)")(
      "top", po::value(&top)->default_value(top), "with --history: how many distinct best")(
      "settle-max", po::value(&audit.settle_max)->default_value(audit.settle_max),
      "longest passive settle before a body counts as never at rest, s")(
      "rest-speed", po::value(&audit.rest_speed)->default_value(audit.rest_speed),
      "every part slower than this is at rest, m/s")(
      "rest-window", po::value(&audit.rest_window)->default_value(audit.rest_window),
      "for this long in a row, s")("measure",
                                   po::value(&audit.measure)->default_value(audit.measure),
                                   "time a body at rest is watched for creep, s")(
      "driven", po::value(&audit.driven)->default_value(audit.driven),
      "time with the controller on, s (0: no driven run)")(
      "max-creep", po::value(&max_creep)->default_value(max_creep),
      "largest creep of a body at rest over --measure s, m")(
      "max-passive-gain", po::value(&max_passive_gain)->default_value(max_passive_gain),
      "largest unexplained energy rise of a passive body, x weight x length")(
      "config,c", po::value(&config_path),
      "INI file with settings (command line wins; an experiment file's [evolution] and [run] "
      "keys are passed over)")("tsv", po::value(&tsv_path), "write one row per body to this file")(
      "save-broken", po::value(&broken_dir),
      "write the genome of every body that broke a check to this directory (text form)");
  OptionOrigins origins;
  po::variables_map vm =
      parseOptions(argc, argv, cli, schema, nullptr, "config", &origins, kEvolveOnlySections);
  if (vm.count("help")) {
    std::cout << optionsHelp(cli, schema) << "\n";
    return 0;
  }
  checkSettings(schema, origins);
  std::uint64_t seed = 0;
  if (!parseSeed(seed_text, seed))
    throw Error(ExitCode::usage, "the argument ('" + seed_text +
                                     "') for option '--seed' is invalid: not a seed (0..2^64-1)");
  auto positive = [](const char* name, double value, bool zero_ok) {
    if (!std::isfinite(value) || value < 0 || (!zero_ok && value == 0))
      throw Error(ExitCode::usage, std::string("--") + name + " " + std::to_string(value) +
                                       ": must be " + (zero_ok ? ">= 0" : "> 0"));
  };
  positive("settle-max", audit.settle_max, false);
  positive("rest-speed", audit.rest_speed, false);
  positive("rest-window", audit.rest_window, false);
  positive("measure", audit.measure, false);
  positive("driven", audit.driven, true);
  positive("max-creep", max_creep, true);
  positive("max-passive-gain", max_passive_gain, true);

  // the bodies: files first, then the histories' best, then random genomes (viable ones only)
  const Encoding& encoding = settings.encoding();
  std::vector<Candidate> candidates;
  for (const std::string& path : genome_paths) {
    Genotype genome = readGenomeFile(path);
    try {
      encoding.validate(genome);
    } catch (const GenomeError& e) {
      throw InputError(path + ": " + e.what());
    }
    candidates.push_back({path, genome});
  }
  for (const std::string& path : history_paths) {
    for (Candidate& candidate : bestOfHistory(path, top))
      candidates.push_back(std::move(candidate));
  }
  for (std::uint64_t k = 0, made = 0; made < random; ++k) {
    Genotype genome = encoding.random(seed, 0, k);
    if (!isViable(genome, settings))
      continue;
    candidates.push_back({"random " + std::to_string(k), genome});
    ++made;
  }
  std::ofstream tsv;
  if (!tsv_path.empty()) {
    tsv.open(tsv_path);
    if (!tsv)
      throw Error(ExitCode::output_file, "--tsv " + tsv_path + ": cannot be written");
    tsv << "body\tparts\trest_status\tat_rest\trest_time\tcreep\trise\tlater_creep\tpassive_gain\t"
           "driven_status\tdriven_gain\tenergy_scale\n";
  }

  // audit every body
  const PhysicsSettings& physics = settings.physics();
  const Environment environment = settings.environment();
  Spread creep, passive_gain, driven_gain;
  std::size_t born = 0, rested = 0, dying_out = 0;
  std::map<std::string, std::size_t> driven_ends;
  std::vector<std::string> broken;
  for (const Candidate& candidate : candidates) {
    Creature creature = encoding.develop(candidate.genome);
    RestAudit rest = auditRest(creature.body, environment, physics, audit);
    if (rest.status == EvalStatus::invalid_body || rest.status == EvalStatus::self_penetration)
      continue;
    ++born;
    DrivenAudit driven;
    if (audit.driven > 0)
      driven = auditDriven(creature.body, creature.controller.get(), environment, physics, audit);
    const double passive = rest.unexplained / rest.energy_scale;
    passive_gain.values.push_back(passive);
    const double driven_share = audit.driven > 0 ? driven.unexplained / driven.energy_scale : 0.0;
    driven_gain.values.push_back(driven_share);
    if (rest.at_rest) {
      ++rested;
      creep.values.push_back(rest.creep);
      dying_out += rest.creep > max_creep && rest.later_creep <= 0.5 * rest.creep;
    }
    if (driven.status != EvalStatus::ok)
      ++driven_ends[std::string(statusName(driven.status)) + ": " + driven.message.substr(0, 40)];

    // what breaks a check (its genome kept on request)
    const std::size_t broken_before = broken.size();
    char line[512];
    if (rest.status != EvalStatus::ok) {
      std::snprintf(line, sizeof line, "%s: passive run ended %s: %s", candidate.source.c_str(),
                    statusName(rest.status), rest.message.c_str());
      broken.push_back(line);
    } else if (rest.at_rest && rest.creep > max_creep && rest.later_creep > 0.5 * rest.creep) {
      std::snprintf(line, sizeof line,
                    "%s: crept %.3g mm in %g s at rest (rise %.3g mm), then %.3g mm in as long",
                    candidate.source.c_str(), rest.creep * 1e3, audit.measure, rest.rise * 1e3,
                    rest.later_creep * 1e3);
      broken.push_back(line);
    } else if (passive > max_passive_gain) {
      std::snprintf(line, sizeof line, "%s: passive energy rose %.3g J unexplained (%.3g x %.3g J)",
                    candidate.source.c_str(), rest.unexplained, passive, rest.energy_scale);
      broken.push_back(line);
    }
    if (!broken_dir.empty() && broken.size() > broken_before)
      saveBroken(broken_dir, candidate);
    if (tsv) {
      tsv << candidate.source << '\t' << creature.body.parts.size() << '\t'
          << statusName(rest.status) << '\t' << rest.at_rest << '\t' << rest.rest_time << '\t'
          << rest.creep << '\t' << rest.rise << '\t' << rest.later_creep << '\t' << passive << '\t'
          << (audit.driven > 0 ? statusName(driven.status) : "-") << '\t' << driven_share << '\t'
          << rest.energy_scale << '\n';
    }
  }

  // the report
  std::printf("bodies         %zu (%zu genome files, %zu from histories, %zu random, seed %s)\n",
              candidates.size(), genome_paths.size(),
              candidates.size() - genome_paths.size() - random, random, seed_text.c_str());
  std::printf(
      "physics        %s world, step %g s, %d substeps, %d iterations (tolerance %g m/s), "
      "self_collision %s, friction_anchors %s, ground_contact_corners %s, contact_slop %g m\n",
      physics.world.c_str(), physics.time_step, physics.substeps, physics.solver_iterations,
      physics.solver_tolerance, physics.self_collision ? "true" : "false",
      physics.friction_anchors ? "true" : "false",
      physics.ground_contact_corners ? "true" : "false", physics.contact_slop);
  std::printf("born           %zu (%zu refused at birth)\n", born, candidates.size() - born);
  std::printf("at rest        %zu within %g s (%zu still moving: their energy is audited)\n",
              rested, audit.settle_max, born - rested);
  std::printf(
      "creep          over %g s at rest: median %.4f mm, 99%% %.4f mm, max %.4f mm "
      "(limit %g mm; %zu above it but dying out)\n",
      audit.measure, creep.at(0.5) * 1e3, creep.at(0.99) * 1e3, creep.at(1) * 1e3, max_creep * 1e3,
      dying_out);
  std::printf(
      "energy passive unexplained rise, x weight x length: median %.2e, 99%% %.2e, max "
      "%.2e (limit %g)\n",
      passive_gain.at(0.5), passive_gain.at(0.99), passive_gain.at(1), max_passive_gain);
  if (audit.driven > 0) {
    std::printf(
        "energy driven  unexplained rise over %g s, x weight x length: median %.2e, 99%% "
        "%.2e, max %.2e (physics.max_energy_gain %g)\n",
        audit.driven, driven_gain.at(0.5), driven_gain.at(0.99), driven_gain.at(1),
        physics.max_energy_gain);
    for (const auto& [end, count] : driven_ends)
      std::printf("driven ended   %zu x %s...\n", count, end.c_str());
  }
  for (const std::string& line : broken)
    std::printf("BROKEN         %s\n", line.c_str());
  std::printf("audit          %s\n",
              broken.empty() ? "every check holds"
                             : (std::to_string(broken.size()) + " bodies broke a check").c_str());
  return broken.empty() ? 0 : static_cast<int>(ExitCode::audit_failed);
}

}  // namespace cambrian
