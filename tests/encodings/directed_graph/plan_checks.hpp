// Test helpers: a developed creature seen as one plan (body, neurons, effector wires and
// oscillators), invariants every developed plan must satisfy, and exact plan comparison.
#pragma once

#include "cambrian/body_plan.hpp"
#include "cambrian/encodings.hpp"

#include "brain/controller_sum.hpp"
#include "brain/neural_network.hpp"
#include "brain/sine_oscillators.hpp"
#include "encodings/directed_graph/encoding.hpp"
#include "encodings/directed_graph/genome.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace cambrian::graph {

/// An effector as the development tests see it: the body's, with its wire and oscillator.
struct FlatEffector {
  int part = 0;
  int dof = 0;
  Wire input;
  JointControllerGene oscillator;
};

/// A developed creature seen as one plan.
struct FlatPlan {
  std::vector<PartPlan> parts;
  std::vector<SensorPlan> sensors;
  std::vector<NeuronPlan> neurons;
  std::vector<FlatEffector> effectors;
  bool truncated = false;
  BodyPlan body;
  std::shared_ptr<const ControllerPlan> controller;

  int signalCount() const { return static_cast<int>(sensors.size() + neurons.size()); }
  int neuronSignal(int n) const { return static_cast<int>(sensors.size()) + n; }
  int jointCount() const { return body.jointCount(); }
  int degreesOfFreedom() const { return body.degreesOfFreedom(); }
  double totalMass() const { return body.totalMass(); }
  double totalVolume() const { return body.totalVolume(); }
};

/// The creature as one plan: the network's neurons and wires, and the oscillators when its
/// controller adds them (a network alone: every oscillator off).
inline FlatPlan flatten(const Creature& creature) {
  FlatPlan flat;
  flat.body = creature.body;
  flat.controller = creature.controller;
  flat.parts = creature.body.parts;
  flat.sensors = creature.body.sensors;
  flat.truncated = creature.body.truncated;
  const NeuralNetworkPlan* network = nullptr;
  const SineOscillatorsPlan* sine = nullptr;
  if (const auto* sum = dynamic_cast<const ControllerSumPlan*>(creature.controller.get())) {
    network = dynamic_cast<const NeuralNetworkPlan*>(sum->parts.at(0).get());
    sine = dynamic_cast<const SineOscillatorsPlan*>(sum->parts.at(1).get());
  } else {
    network = dynamic_cast<const NeuralNetworkPlan*>(creature.controller.get());
  }
  EXPECT_NE(network, nullptr) << "the directed graph develops a network";
  if (!network)
    return flat;
  EXPECT_EQ(network->sensor_count, creature.body.sensors.size());
  EXPECT_EQ(network->effector_inputs.size(), creature.body.effectors.size());
  flat.neurons = network->neurons;
  for (std::size_t e = 0; e < creature.body.effectors.size(); ++e) {
    FlatEffector effector;
    effector.part = creature.body.effectors[e].part;
    effector.dof = creature.body.effectors[e].dof;
    effector.input = network->effector_inputs.at(e);
    if (sine) {
      const SineOscillator& o = sine->oscillators.at(e);
      effector.oscillator =
          JointControllerGene{o.enabled, o.amplitude, o.frequency, o.phase, o.offset};
    }
    flat.effectors.push_back(effector);
  }
  return flat;
}

/// develop() seen as one plan.
inline FlatPlan flatDevelop(const Genome& genome, const GenomeLimits& limits) {
  return flatten(develop(genome, limits));
}

/// True when every component of v is finite.
inline bool finite(Vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// True when every component of q is finite.
inline bool finite(Quat q) {
  return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

/// True when wire reads a constant or a signal of plan.
inline bool wireInRange(const Wire& wire, const FlatPlan& plan) {
  return wire.signal >= -1 && wire.signal < plan.signalCount() && std::isfinite(wire.weight);
}

/// Checks the structural invariants of a developed plan: part count within limits, parents
/// first, finite poses, sizes within limits, joints that meet at their pivots, wires in range.
inline void expectPlanConsistent(const FlatPlan& plan, const GenomeLimits& limits) {
  // parts: count, order, size, pose
  ASSERT_GE(plan.parts.size(), 1u);
  ASSERT_LE(static_cast<int>(plan.parts.size()), limits.max_parts);
  EXPECT_EQ(plan.parts[0].parent, -1);
  for (std::size_t i = 0; i < plan.parts.size(); ++i) {
    const PartPlan& part = plan.parts[i];
    const std::string where = "part " + std::to_string(i);
    for (int k = 0; k < 3; ++k) {
      EXPECT_GE(part.size[k], limits.min_part_size) << where;
      EXPECT_LE(part.size[k], limits.max_part_size) << where;
    }
    EXPECT_TRUE(finite(part.pose.position)) << where;
    EXPECT_TRUE(finite(part.pose.rotation)) << where;
    EXPECT_TRUE(std::isfinite(part.mass) && part.mass > 0) << where;
    if (i == 0) {
      continue;
    }
    ASSERT_GE(part.parent, 0) << where;
    ASSERT_LT(part.parent, static_cast<int>(i)) << where;
    // the joint point is the same seen from both parts
    const PartPlan& parent = plan.parts[part.parent];
    const Vec3 from_parent = apply(parent.pose, part.pivot_in_parent);
    const Vec3 from_child = apply(part.pose, part.pivot_in_child);
    EXPECT_LT(norm(from_parent - from_child), 1e-9) << where;
    const Vec3 probe{0.3, -0.7, 0.2};
    const Vec3 composed = rotate(parent.pose.rotation, rotate(part.parent_to_child, probe));
    EXPECT_LT(norm(composed - rotate(part.pose.rotation, probe)), 1e-9) << where;
    EXPECT_GT(part.cross_section, 0) << where;
  }

  // sensors, neurons and effectors point at things that exist
  for (const SensorPlan& sensor : plan.sensors) {
    EXPECT_GE(sensor.part, 0);
    EXPECT_LT(sensor.part, static_cast<int>(plan.parts.size()));
  }
  for (std::size_t n = 0; n < plan.neurons.size(); ++n) {
    EXPECT_LT(plan.neurons[n].part, static_cast<int>(plan.parts.size()));
    for (const Wire& wire : plan.neurons[n].inputs) {
      EXPECT_TRUE(wireInRange(wire, plan)) << "neuron " << n << " signal " << wire.signal;
    }
  }
  for (const FlatEffector& effector : plan.effectors) {
    ASSERT_GE(effector.part, 1);
    ASSERT_LT(effector.part, static_cast<int>(plan.parts.size()));
    EXPECT_LT(effector.dof, degreesOfFreedom(plan.parts[effector.part].joint));
    EXPECT_TRUE(wireInRange(effector.input, plan));
  }
}

/// Checks that two plans are identical, bit for bit.
inline void expectSamePlan(const FlatPlan& a, const FlatPlan& b) {
  ASSERT_EQ(a.parts.size(), b.parts.size());
  EXPECT_EQ(a.truncated, b.truncated);
  for (std::size_t i = 0; i < a.parts.size(); ++i) {
    const PartPlan& p = a.parts[i];
    const PartPlan& q = b.parts[i];
    EXPECT_EQ(p.node, q.node);
    EXPECT_EQ(p.parent, q.parent);
    EXPECT_EQ(p.connection, q.connection);
    EXPECT_EQ(p.size, q.size);
    EXPECT_EQ(p.mass, q.mass);
    EXPECT_EQ(p.pose.position, q.pose.position);
    EXPECT_EQ(p.pose.rotation, q.pose.rotation);
    EXPECT_EQ(p.parent_to_child, q.parent_to_child);
    EXPECT_EQ(p.pivot_in_parent, q.pivot_in_parent);
    EXPECT_EQ(p.pivot_in_child, q.pivot_in_child);
    EXPECT_EQ(p.axes, q.axes);
    EXPECT_EQ(p.cross_section, q.cross_section);
    EXPECT_EQ(p.reflected, q.reflected);
    EXPECT_EQ(p.shape, q.shape);
    EXPECT_EQ(p.material, q.material);
  }
  ASSERT_EQ(a.sensors.size(), b.sensors.size());
  for (std::size_t i = 0; i < a.sensors.size(); ++i) {
    EXPECT_EQ(a.sensors[i].kind, b.sensors[i].kind);
    EXPECT_EQ(a.sensors[i].part, b.sensors[i].part);
    EXPECT_EQ(a.sensors[i].axis, b.sensors[i].axis);
  }
  ASSERT_EQ(a.neurons.size(), b.neurons.size());
  for (std::size_t i = 0; i < a.neurons.size(); ++i) {
    EXPECT_EQ(a.neurons[i].function, b.neurons[i].function);
    EXPECT_EQ(a.neurons[i].parameter, b.neurons[i].parameter);
    EXPECT_EQ(a.neurons[i].part, b.neurons[i].part);
    EXPECT_EQ(a.neurons[i].inputs, b.neurons[i].inputs);
  }
  ASSERT_EQ(a.effectors.size(), b.effectors.size());
  for (std::size_t i = 0; i < a.effectors.size(); ++i) {
    EXPECT_EQ(a.effectors[i].part, b.effectors[i].part);
    EXPECT_EQ(a.effectors[i].dof, b.effectors[i].dof);
    EXPECT_EQ(a.effectors[i].input, b.effectors[i].input);
    EXPECT_EQ(a.effectors[i].oscillator, b.effectors[i].oscillator);
  }
}

}  // namespace cambrian::graph
