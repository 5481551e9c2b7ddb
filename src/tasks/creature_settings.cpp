// cambrian: the creature settings — every registered plug-in with its settings, the choice of
// each, and their keys in one schema.
#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"
#include "cambrian/evaluate.hpp"

#include "core/settings.hpp"
#include "physics/environment.hpp"
#include "physics/physics_settings.hpp"
#include "tasks/episode.hpp"
#include "tasks/task.hpp"

#include <algorithm>

namespace cambrian {

struct CreatureSettings::State {
  std::string encoding_name = "directed_graph";
  std::string task_name = "walk";
  std::string environment_name = "plane";
  std::vector<std::unique_ptr<Encoding>> encodings;  // every registered one, configured
  std::vector<std::unique_ptr<Task>> tasks;
  std::vector<std::unique_ptr<EnvironmentKind>> environments;
  PhysicsSettings physics;
  EpisodeSettings episode;
  SettingsSchema schema;  // bound to the members above

  // fresh plug-ins at their defaults
  State() {
    for (const Encoding* encoding : cambrian::encodings())
      encodings.push_back(encoding->clone());
    for (const Task* task : cambrian::tasks())
      tasks.push_back(task->clone());
    for (const EnvironmentKind* kind : environmentKinds())
      environments.push_back(kind->clone());
  }

  // a copy: cloned plug-ins with their settings
  State(const State& other)
      : encoding_name(other.encoding_name),
        task_name(other.task_name),
        environment_name(other.environment_name),
        physics(other.physics),
        episode(other.episode) {
    for (const auto& encoding : other.encodings)
      encodings.push_back(encoding->clone());
    for (const auto& task : other.tasks)
      tasks.push_back(task->clone());
    for (const auto& kind : other.environments)
      environments.push_back(kind->clone());
  }

  // every key, bound to this state
  void declare(SettingsSchema& s) {
    s.add("genome.encoding", encoding_name, "genome encoding: " + joined(encodingNames()))
        .oneOf(encodingNames());
    for (auto& encoding : encodings)
      encoding->declareSettings(s);
    physics.declareSettings(s);
    s.describeSection("task", "[task] what is measured");
    std::string task_help;
    for (const auto& task : tasks)
      task_help += (task_help.empty() ? "" : " | ") + task->name() + " (" + task->summary() + ")";
    s.add("task.name", task_name, task_help).oneOf(taskNames());
    episode.declareSettings(s);
    for (auto& task : tasks)
      task->declareSettings(s);
    s.describeSection("environment", "[environment] what surrounds the creature");
    s.add("environment.name", environment_name, "the environment: " + joined(environmentNames()))
        .oneOf(environmentNames());
    for (auto& kind : environments)
      kind->declareSettings(s);
  }

  static std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names)
      text += (text.empty() ? "" : " | ") + name;
    return text;
  }

  template <class T>
  static const T& chosen(const std::vector<std::unique_ptr<T>>& list, const std::string& name,
                         const char* key) {
    for (const auto& item : list) {
      if (item->name() == name)
        return *item;
    }
    throw ConfigError(std::string(key) + " = " + name + ": no such choice");
  }
};

CreatureSettings::CreatureSettings() : state_(std::make_unique<State>()) {
  state_->declare(state_->schema);
}

CreatureSettings::CreatureSettings(const CreatureSettings& other)
    : state_(std::make_unique<State>(*other.state_)) {
  state_->declare(state_->schema);
}

CreatureSettings& CreatureSettings::operator=(const CreatureSettings& other) {
  if (this != &other) {
    state_ = std::make_unique<State>(*other.state_);
    state_->declare(state_->schema);
  }
  return *this;
}

CreatureSettings::~CreatureSettings() = default;

void CreatureSettings::set(const std::string& key, const std::string& value) {
  try {
    state_->schema.set(key, value);
  } catch (const SettingTypeError& e) {
    throw ConfigError(e.what());
  }
}

std::string CreatureSettings::value(const std::string& key) const {
  Setting* setting = state_->schema.find(key);
  if (!setting)
    throw ConfigError("unrecognised option '" + key + "'");
  return setting->text();
}

void CreatureSettings::check() const {
  state_->schema.check();
}

std::string CreatureSettings::iniText() const {
  return state_->schema.iniText();
}

void CreatureSettings::declareSettings(SettingsSchema& schema) {
  state_->declare(schema);
}

const Encoding& CreatureSettings::encoding() const {
  return State::chosen(state_->encodings, state_->encoding_name, "genome.encoding");
}

const Task& CreatureSettings::task() const {
  return State::chosen(state_->tasks, state_->task_name, "task.name");
}

const PhysicsSettings& CreatureSettings::physics() const {
  return state_->physics;
}

PhysicsSettings& CreatureSettings::physics() {
  return state_->physics;
}

const EpisodeSettings& CreatureSettings::episode() const {
  return state_->episode;
}

Environment CreatureSettings::environment() const {
  return State::chosen(state_->environments, state_->environment_name, "environment.name")
      .build(state_->physics);
}

}  // namespace cambrian
