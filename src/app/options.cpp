#include "options.hpp"

#include "cambrian/error.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace cambrian {

namespace {

// range check helper: throws ConfigError "key = value: must be ..."
void require(bool ok, const std::string& key, double value, const std::string& rule) {
  if (!ok || std::isnan(value)) {
    std::ostringstream message;
    message << key << " = " << value << ": " << rule;
    throw ConfigError(message.str());
  }
}

}  // namespace

po::options_description creatureOptions(CreatureSettings& s) {
  po::options_description all("Creature settings (INI sections [genome], [physics], [task])");

  // genome limits
  po::options_description genome("[genome] limits");
  genome.add_options()("genome.max_nodes",
                       po::value(&s.limits.max_nodes)->default_value(s.limits.max_nodes),
                       "maximum genes (graph nodes) per genome")(
      "genome.max_connections",
      po::value(&s.limits.max_connections)->default_value(s.limits.max_connections),
      "maximum connections per genome")(
      "genome.max_parts", po::value(&s.limits.max_parts)->default_value(s.limits.max_parts),
      "maximum body parts after development")(
      "genome.max_recursive_limit",
      po::value(&s.limits.max_recursive_limit)->default_value(s.limits.max_recursive_limit),
      "largest recursive limit of a node")(
      "genome.max_neurons_per_node",
      po::value(&s.limits.max_neurons_per_node)->default_value(s.limits.max_neurons_per_node),
      "local neurons per node")(
      "genome.max_brain_neurons",
      po::value(&s.limits.max_brain_neurons)->default_value(s.limits.max_brain_neurons),
      "global (brain) neurons")(
      "genome.min_part_size",
      po::value(&s.limits.min_part_size)->default_value(s.limits.min_part_size),
      "smallest box side, m")(
      "genome.max_part_size",
      po::value(&s.limits.max_part_size)->default_value(s.limits.max_part_size),
      "largest box side, m");
  all.add(genome);

  // physics
  po::options_description physics("[physics] world");
  physics.add_options()("physics.time_step",
                        po::value(&s.physics.time_step)->default_value(s.physics.time_step),
                        "fixed physics step, s")(
      "physics.substeps", po::value(&s.physics.substeps)->default_value(s.physics.substeps),
      "Bullet steps per time step (torques re-applied each)")(
      "physics.gravity", po::value(&s.physics.gravity)->default_value(s.physics.gravity),
      "gravity, m/s^2 (downwards)")(
      "physics.ground_friction",
      po::value(&s.physics.ground_friction)->default_value(s.physics.ground_friction),
      "ground friction coefficient")(
      "physics.restitution",
      po::value(&s.physics.restitution)->default_value(s.physics.restitution),
      "restitution of contacts")(
      "physics.joint_damping",
      po::value(&s.physics.joint_damping)->default_value(s.physics.joint_damping),
      "passive joint damping, N m s/rad")(
      "physics.strength_per_area",
      po::value(&s.physics.strength_per_area)->default_value(s.physics.strength_per_area),
      "joint torque per m^2 of the smaller cross-section, N m/m^2")(
      "physics.actuation", po::value(&s.actuation_name)->default_value(s.actuation_name),
      "motor (Chaumont: velocity motor at saturation, torque limit from the command) | torque "
      "(Sims: explicit joint torque)")(
      "physics.motor_speed",
      po::value(&s.physics.motor_speed)->default_value(s.physics.motor_speed),
      "target speed of a saturated motor, rad/s")(
      "physics.self_collision",
      po::value(&s.physics.self_collision)->default_value(s.physics.self_collision),
      "parts collide with each other while moving (Sims), not only with the ground; overlap at "
      "birth is rejected either way")(
      "physics.solver_iterations",
      po::value(&s.physics.solver_iterations)->default_value(s.physics.solver_iterations),
      "constraint solver iterations per step")(
      "physics.max_speed", po::value(&s.physics.max_speed)->default_value(s.physics.max_speed),
      "a part faster than this has exploded, m/s")(
      "physics.max_displacement",
      po::value(&s.physics.max_displacement)->default_value(s.physics.max_displacement),
      "a part farther than this from its start has exploded, m")(
      "physics.penetration_tolerance",
      po::value(&s.physics.penetration_tolerance)->default_value(s.physics.penetration_tolerance),
      "overlap allowed between non-adjacent parts at birth, m")(
      "physics.max_wall_seconds",
      po::value(&s.physics.max_wall_seconds)->default_value(s.physics.max_wall_seconds),
      "wall-clock bound of one evaluation, s (0 = none)");
  all.add(physics);

  // task
  po::options_description task("[task] what is measured");
  task.add_options()("task.name", po::value(&s.task_name)->default_value(s.task_name),
                     "walk | jump | synthetic")(
      "task.evaluation_time",
      po::value(&s.task.evaluation_time)->default_value(s.task.evaluation_time),
      "measured time, s")("task.settle_time",
                          po::value(&s.task.settle_time)->default_value(s.task.settle_time),
                          "brain off before the trial, s")(
      "task.trial_time", po::value(&s.task.trial_time)->default_value(s.task.trial_time),
      "brain on, unmeasured, s")(
      "task.resettle_time", po::value(&s.task.resettle_time)->default_value(s.task.resettle_time),
      "brain off again before measuring, s")(
      "task.rest_check", po::value(&s.task.rest_check)->default_value(s.task.rest_check),
      "Chaumont's rest rule: each settle phase lasts until the body is at rest (at least "
      "task.settle_time / task.resettle_time); no rest within task.settle_max_time: unstable")(
      "task.rest_speed", po::value(&s.task.rest_speed)->default_value(s.task.rest_speed),
      "rest check: largest speed of any part's centre of mass counted as rest, m/s")(
      "task.rest_time", po::value(&s.task.rest_time)->default_value(s.task.rest_time),
      "rest check: how long the body must stay at rest, s")(
      "task.settle_max_time",
      po::value(&s.task.settle_max_time)->default_value(s.task.settle_max_time),
      "rest check: the longest a settle phase may last, s")(
      "task.normalisation", po::value(&s.normalisation_name)->default_value(s.normalisation_name),
      "walk fitness: none | chaumont | volume")(
      "task.chaumont_k", po::value(&s.task.chaumont_k)->default_value(s.task.chaumont_k),
      "k of the k^N complexity bonus (chaumont normalisation)")(
      "task.synthetic_cost_us",
      po::value(&s.task.synthetic_cost_us)->default_value(s.task.synthetic_cost_us),
      "synthetic task: busy work per evaluation, microseconds")(
      "task.synthetic_cost_per_gene_us",
      po::value(&s.task.synthetic_cost_per_gene_us)
          ->default_value(s.task.synthetic_cost_per_gene_us),
      "synthetic task: extra busy work per genome node, microseconds")(
      "task.synthetic_noise",
      po::value(&s.task.synthetic_noise)->default_value(s.task.synthetic_noise),
      "synthetic task, uniform distribution: relative spread of the cost (0..1)")(
      "task.synthetic_distribution",
      po::value(&s.synthetic_distribution_name)->default_value(s.synthetic_distribution_name),
      "synthetic task: law of the cost around its mean (base + per-gene cost): uniform "
      "(synthetic_noise) | lognormal (synthetic_cv) | fixed")(
      "task.synthetic_cv", po::value(&s.task.synthetic_cv)->default_value(s.task.synthetic_cv),
      "synthetic task, lognormal distribution: coefficient of variation of the cost (0..4)");
  all.add(task);
  return all;
}

void finishCreatureSettings(CreatureSettings& s) {
  // enumerations given as words
  if (s.task_name == "walk") {
    s.task.kind = TaskKind::walk;
  } else if (s.task_name == "jump") {
    s.task.kind = TaskKind::jump;
  } else if (s.task_name == "synthetic") {
    s.task.kind = TaskKind::synthetic;
  } else {
    throw ConfigError("task.name = " + s.task_name + ": must be walk, jump or synthetic");
  }
  if (s.normalisation_name == "none") {
    s.task.normalisation = WalkNormalisation::none;
  } else if (s.normalisation_name == "chaumont") {
    s.task.normalisation = WalkNormalisation::chaumont;
  } else if (s.normalisation_name == "volume") {
    s.task.normalisation = WalkNormalisation::volume;
  } else {
    throw ConfigError("task.normalisation = " + s.normalisation_name +
                      ": must be none, chaumont or volume");
  }
  if (s.actuation_name == "motor") {
    s.physics.actuation = Actuation::saturated_motor;
  } else if (s.actuation_name == "torque") {
    s.physics.actuation = Actuation::torque;
  } else {
    throw ConfigError("physics.actuation = " + s.actuation_name + ": must be motor or torque");
  }

  // genome limits
  const GenomeLimits& g = s.limits;
  require(g.max_nodes >= 1 && g.max_nodes <= 1000, "genome.max_nodes", g.max_nodes,
          "must be in 1..1000");
  require(g.max_connections >= 0 && g.max_connections <= 4000, "genome.max_connections",
          g.max_connections, "must be in 0..4000");
  require(g.max_parts >= 1 && g.max_parts <= 1000, "genome.max_parts", g.max_parts,
          "must be in 1..1000");
  require(g.max_recursive_limit >= 1 && g.max_recursive_limit <= 64, "genome.max_recursive_limit",
          g.max_recursive_limit, "must be in 1..64");
  require(g.max_neurons_per_node >= 0 && g.max_neurons_per_node <= 64,
          "genome.max_neurons_per_node", g.max_neurons_per_node, "must be in 0..64");
  require(g.max_brain_neurons >= 0 && g.max_brain_neurons <= 256, "genome.max_brain_neurons",
          g.max_brain_neurons, "must be in 0..256");
  require(g.min_part_size > 0 && std::isfinite(g.min_part_size), "genome.min_part_size",
          g.min_part_size, "must be > 0 and finite");
  require(g.max_part_size >= g.min_part_size && std::isfinite(g.max_part_size),
          "genome.max_part_size", g.max_part_size, "must be >= genome.min_part_size and finite");

  // physics
  const PhysicsSettings& p = s.physics;
  require(p.time_step > 0 && p.time_step <= 0.1, "physics.time_step", p.time_step,
          "must be in (0, 0.1] s");
  require(p.substeps >= 1 && p.substeps <= 100, "physics.substeps", p.substeps,
          "must be in 1..100");
  require(p.gravity >= 0 && std::isfinite(p.gravity), "physics.gravity", p.gravity, "must be >= 0");
  require(p.ground_friction >= 0 && std::isfinite(p.ground_friction), "physics.ground_friction",
          p.ground_friction, "must be >= 0");
  require(p.restitution >= 0 && p.restitution <= 1, "physics.restitution", p.restitution,
          "must be in [0, 1]");
  require(p.joint_damping >= 0 && std::isfinite(p.joint_damping), "physics.joint_damping",
          p.joint_damping, "must be >= 0");
  require(p.strength_per_area >= 0 && std::isfinite(p.strength_per_area),
          "physics.strength_per_area", p.strength_per_area, "must be >= 0");
  require(p.motor_speed > 0 && std::isfinite(p.motor_speed), "physics.motor_speed", p.motor_speed,
          "must be > 0");
  require(p.solver_iterations >= 1 && p.solver_iterations <= 1000, "physics.solver_iterations",
          p.solver_iterations, "must be in 1..1000");
  require(p.max_speed > 0 && std::isfinite(p.max_speed), "physics.max_speed", p.max_speed,
          "must be > 0 and finite");
  require(p.max_displacement > 0 && std::isfinite(p.max_displacement), "physics.max_displacement",
          p.max_displacement, "must be > 0 and finite");
  require(p.penetration_tolerance >= 0 && std::isfinite(p.penetration_tolerance),
          "physics.penetration_tolerance", p.penetration_tolerance, "must be >= 0 and finite");
  require(p.max_wall_seconds >= 0 && std::isfinite(p.max_wall_seconds), "physics.max_wall_seconds",
          p.max_wall_seconds, "must be >= 0 and finite (0 = no bound)");

  // task
  const TaskSettings& t = s.task;
  require(t.evaluation_time > 0 && t.evaluation_time <= 3600, "task.evaluation_time",
          t.evaluation_time, "must be in (0, 3600] s");
  require(t.settle_time >= 0 && t.settle_time <= 3600, "task.settle_time", t.settle_time,
          "must be in [0, 3600] s");
  require(t.trial_time >= 0 && t.trial_time <= 3600, "task.trial_time", t.trial_time,
          "must be in [0, 3600] s");
  require(t.resettle_time >= 0 && t.resettle_time <= 3600, "task.resettle_time", t.resettle_time,
          "must be in [0, 3600] s");
  require(t.rest_speed > 0 && std::isfinite(t.rest_speed), "task.rest_speed", t.rest_speed,
          "must be > 0 m/s");
  require(t.rest_time >= 0 && t.rest_time <= 3600, "task.rest_time", t.rest_time,
          "must be in [0, 3600] s");
  require(t.settle_max_time >= 0 && t.settle_max_time <= 3600, "task.settle_max_time",
          t.settle_max_time, "must be in [0, 3600] s");
  // with the rest check on, a settle phase must have room for its minimum and for the rest
  if (t.rest_check) {
    require(t.settle_max_time >= std::max({t.settle_time, t.resettle_time, t.rest_time}),
            "task.settle_max_time", t.settle_max_time,
            "must be >= task.settle_time, task.resettle_time and task.rest_time when "
            "task.rest_check is on");
  }
  require(t.chaumont_k > 0 && std::isfinite(t.chaumont_k), "task.chaumont_k", t.chaumont_k,
          "must be > 0 and finite");
  require(t.synthetic_cost_us >= 0 && t.synthetic_cost_us <= 3.6e9, "task.synthetic_cost_us",
          t.synthetic_cost_us, "must be in [0, 3.6e9] us");
  require(t.synthetic_cost_per_gene_us >= 0 && t.synthetic_cost_per_gene_us <= 3.6e9,
          "task.synthetic_cost_per_gene_us", t.synthetic_cost_per_gene_us,
          "must be in [0, 3.6e9] us");
  require(t.synthetic_noise >= 0 && t.synthetic_noise <= 1, "task.synthetic_noise",
          t.synthetic_noise, "must be in [0, 1]");
  require(t.synthetic_cv >= 0 && t.synthetic_cv <= 4, "task.synthetic_cv", t.synthetic_cv,
          "must be in [0, 4]");
  if (s.synthetic_distribution_name == "uniform") {
    s.task.synthetic_distribution = SyntheticDistribution::uniform;
  } else if (s.synthetic_distribution_name == "lognormal") {
    s.task.synthetic_distribution = SyntheticDistribution::lognormal;
  } else if (s.synthetic_distribution_name == "fixed") {
    s.task.synthetic_distribution = SyntheticDistribution::fixed;
  } else {
    throw ConfigError("task.synthetic_distribution = " + s.synthetic_distribution_name +
                      ": must be uniform, lognormal or fixed");
  }
}

po::variables_map parseOptions(int argc, const char* const* argv,
                               const po::options_description& cli_only,
                               const po::options_description& settings,
                               const po::positional_options_description* positional,
                               const std::string& config_key, OptionOrigins* origins) {
  po::options_description all;
  all.add(cli_only).add(settings);
  po::variables_map vm;

  // the keys of `vm` given explicitly (not defaults)
  auto givenKeys = [&vm]() {
    std::set<std::string> keys;
    for (const auto& [key, value] : vm) {
      if (!value.defaulted())
        keys.insert(key);
    }
    return keys;
  };

  // command line first: it wins over the file
  try {
    po::command_line_parser parser(argc, argv);
    parser.options(all);
    if (positional)
      parser.positional(*positional);
    po::store(parser.run(), vm);
  } catch (const po::error& e) {
    throw Error(ExitCode::usage, e.what());
  }
  std::set<std::string> command_line = givenKeys();

  // then the INI file, when one is named
  std::string path;
  if (!config_key.empty() && vm.count(config_key)) {
    path = vm[config_key].as<std::string>();
    std::ifstream file(path);
    if (!file)
      throw ConfigError(path + ": cannot open the config file");
    try {
      po::store(po::parse_config_file(file, settings, false), vm);
    } catch (const po::error& e) {
      throw ConfigError(path + ": " + e.what());
    }
  }
  if (origins) {
    origins->command_line = command_line;
    origins->config_file.clear();
    for (const std::string& key : givenKeys()) {
      if (!command_line.count(key))
        origins->config_file.insert(key);
    }
    origins->config_path = path;
  }

  // bind values to variables (a value that does not convert is named with its origin)
  try {
    po::notify(vm);
  } catch (const po::error& e) {
    std::string message = e.what();
    if (!path.empty() && origins) {
      for (const std::string& key : origins->config_file) {
        if (message.find("'" + key + "'") != std::string::npos)
          throw ConfigError(path + ": " + message);
      }
    }
    throw ConfigError(message);
  }
  return vm;
}

void finishCreatureSettings(CreatureSettings& settings, const OptionOrigins& origins) {
  try {
    finishCreatureSettings(settings);
  } catch (const ConfigError& e) {
    throw ConfigError(locateSettingError(e.what(), origins));
  }
}

std::string locateSettingError(const std::string& message, const OptionOrigins& origins) {
  std::string key = message.substr(0, message.find(" = "));
  if (origins.config_file.count(key) && !origins.config_path.empty())
    return origins.config_path + ": " + message;
  if (origins.command_line.count(key))
    return "command line: --" + message;
  return message;
}

std::ostream& operator<<(std::ostream& out, const SeedValue& seed) {
  return out << seed.value;
}

void validate(boost::any& value, const std::vector<std::string>& tokens, SeedValue*, int) {
  po::validators::check_first_occurrence(value);
  const std::string& text = po::validators::get_single_string(tokens);
  SeedValue seed;
  auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), seed.value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size())
    throw po::invalid_option_value(text);
  value = seed;
}

namespace {

// a number as a person writes it: "0.050000000000000003" becomes "0.05"
std::string readableNumber(const std::string& text) {
  char* end = nullptr;
  double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || text.find('.') == std::string::npos)
    return text;
  char shorter[32];
  std::snprintf(shorter, sizeof shorter, "%.12g", value);
  return shorter;
}

// the default as Boost prints it: format_parameter() gives "arg (=default)"; "" when none
std::string rawDefault(const po::option_description& option) {
  boost::any value;
  if (!option.semantic()->apply_default(value))
    return "";
  std::string parameter = option.format_parameter();
  auto at = parameter.find("(=");
  if (at == std::string::npos)
    return "";
  return parameter.substr(at + 2, parameter.size() - at - 3);
}

// whether an option is a true/false flag
bool isFlag(const po::option_description& option) {
  return dynamic_cast<const po::typed_value<bool>*>(option.semantic().get()) != nullptr;
}

// a table cell: pipes escaped so they do not split the cell
std::string tableCell(const std::string& text) {
  std::string cell;
  for (char c : text) {
    if (c == '|')
      cell += '\\';
    cell += c;
  }
  return cell;
}

}  // namespace

std::string optionsMarkdown(const po::options_description& desc) {
  std::ostringstream out;
  std::string section;
  for (const auto& option : desc.options()) {
    // a heading and a table head whenever the section (the key's prefix) changes
    const std::string& key = option->long_name();
    std::string key_section = key.substr(0, key.find('.'));
    if (key_section != section) {
      section = key_section;
      out << (out.tellp() > 0 ? "\n" : "") << "### [" << section << "]\n\n"
          << "| key | default | meaning |\n| --- | --- | --- |\n";
    }

    out << "| `" << key << "` | " << tableCell(readableDefault(*option)) << " | "
        << tableCell(option->description()) << " |\n";
  }
  return out.str();
}

std::string readableDefault(const po::option_description& option) {
  std::string text = rawDefault(option);
  if (isFlag(option) && (text == "0" || text == "1"))
    return text == "1" ? "true" : "false";
  return readableNumber(text);
}

std::string optionsHelp(const po::options_description& desc) {
  std::ostringstream boost_text;
  boost_text << desc;
  std::string text = boost_text.str();
  // each "--key arg (=raw)" made readable, padded so the descriptions stay in their column
  for (const auto& option : desc.options()) {
    std::string raw = rawDefault(*option);
    std::string readable = readableDefault(*option);
    if (raw.empty() || raw == readable)
      continue;
    std::string from = "--" + option->long_name() + " arg (=" + raw + ")";
    std::size_t at = text.find(from);
    if (at == std::string::npos)
      continue;
    std::string to = "--" + option->long_name() + " arg (=" + readable + ")";
    std::size_t after = at + from.size();
    if (to.size() < from.size()) {
      to.append(from.size() - to.size(), ' ');
    } else {
      // a longer default takes the spaces after it, leaving at least one
      std::size_t spaces = 0;
      while (after + spaces < text.size() && text[after + spaces] == ' ')
        ++spaces;
      std::size_t take = std::min(to.size() - from.size(), spaces > 0 ? spaces - 1 : 0);
      text.erase(after, take);
    }
    text.replace(at, from.size(), to);
  }
  return text;
}

}  // namespace cambrian
