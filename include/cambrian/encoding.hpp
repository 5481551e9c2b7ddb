// cambrian: genome encodings as plug-ins. An Encoding makes, checks, varies, writes, reads and
// develops the genomes of one representation (Sims' directed graph first). Everything above it —
// the breeder, the scheduler, the worker, the history, the checkpoint, the commands — holds
// genomes as Genotype values and works through this interface only. docs/design.md says how to
// add an encoding.
#pragma once

#include "cambrian/body_plan.hpp"
#include "cambrian/controller.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace cambrian {

class Encoding;
class Rng;
class SettingsSchema;

/// The decoded genome of some encoding; each encoding derives its own. Immutable once made.
class GenomeData {
 public:
  virtual ~GenomeData() = default;
};

/// A genome of any encoding: the encoding that reads and writes it and the decoded genome, shared
/// and immutable (copies are cheap). Its byte form — a 4-byte encoding tag, a 32-bit format
/// version, then the encoding's fields — is made once and kept. A deferred genotype is made by
/// its recipe when first read (breeding spread over the dispatch of a generation).
class Genotype {
 public:
  /// No genome.
  Genotype() = default;
  /// `data` of `encoding` (which must outlive the genotype; registered encodings live forever).
  Genotype(const Encoding& encoding, std::shared_ptr<const GenomeData> data);
  /// `data` of `encoding` whose byte form is `bytes` (kept, not made again).
  Genotype(const Encoding& encoding, std::shared_ptr<const GenomeData> data,
           std::vector<std::uint8_t> bytes);

  /// A genome of `encoding` that `make` (a pure function, holding copies of what it reads) makes
  /// when it is first read; every copy of the handle shares the one made. `make` must return a
  /// genome of `encoding`.
  static Genotype deferred(const Encoding& encoding, std::function<Genotype()> make);
  /// Whether it holds a genome (made or still to be made).
  explicit operator bool() const { return static_cast<bool>(state_); }
  /// Whether it is made (not deferred, or read since).
  bool made() const;
  /// The encoding that wrote it.
  const Encoding& encoding() const;
  /// The decoded genome.
  const GenomeData& data() const;
  /// The decoded genome as the encoding's own type (checked).
  template <class T>
  const T& as() const {
    const auto* typed = dynamic_cast<const T*>(&data());
    if (!typed)
      wrongType();
    return *typed;
  }
  /// The byte form (tag, version, fields), made on first use.
  const std::vector<std::uint8_t>& bytes() const;
  /// Lets go of the decoded genome where the byte form is made; data() decodes it again when
  /// next read. Rank 0 keeps the creatures it has sent in their byte form alone.
  void dropDecoded() const;
  /// Whether two genotypes have the same byte form.
  friend bool operator==(const Genotype& a, const Genotype& b);

 private:
  [[noreturn]] void wrongType() const;
  // makes a deferred genome now
  void make() const;
  struct State;
  std::shared_ptr<State> state_;
};

/// Sizes of a genome that need no development: the scheduler's cost hint (genes + links) and the
/// synthetic task's work and fitness.
struct GenomeSize {
  std::size_t genes = 0;       ///< classes of parts (graph nodes)
  std::size_t links = 0;       ///< classes of joints (graph connections)
  double total_part_size = 0;  ///< sum over part genes of their mean side, m (0 when none)
};

/// What development makes of a genome: the body and the controller that drives it.
struct Creature {
  BodyPlan body;
  std::shared_ptr<const ControllerPlan> controller;  ///< null: nothing drives the effectors
};

/// The variation operators a breeding scheme may ask for: the Sims / Chaumont scheme's
/// mutation, crossover and graft, and Minemonics' reaper's operators.
enum class Variation : std::uint8_t {
  mutation,
  crossover,
  graft,
  gene_specification,    ///< genes re-drawn, their connections kept
  gene_split,            ///< genes halved, the halves rigidly joined
  gene_purge,            ///< a gene re-drawn and cut off from the others
  branch_specification,  ///< connections re-drawn, their ends kept
  grow_stub,             ///< new connections
  graft_feature,         ///< a gene of a second genome and the genes below it, a few levels deep
  segment_crossover,     ///< a run of genes of each of two genomes, joined (Minemonics)
};
/// Number of Variation values.
constexpr int kVariationKinds = 10;
/// Lower-case variation name ("gene_split").
const char* variationName(Variation variation);

/// A genome representation. An instance carries its settings (limits, operator rates): the
/// experiment's configured instance develops and varies genomes; the registered prototype
/// (default settings) reads and writes them.
class Encoding {
 public:
  virtual ~Encoding() = default;
  /// A copy with the same settings.
  virtual std::unique_ptr<Encoding> clone() const = 0;
  /// The name users give (genome.encoding = NAME).
  virtual std::string name() const = 0;
  /// The first four bytes of its byte form.
  virtual std::array<char, 4> tag() const = 0;
  /// The first word of its text form ("cambrian-genome").
  virtual std::string textHeader() const = 0;

  /// Declares its settings (limits, operator rates) in `schema`, bound to this instance.
  virtual void declareSettings(SettingsSchema& schema) = 0;

  /// A random genome, a pure function of (seed, generation, individual) and the settings.
  virtual Genotype random(std::uint64_t seed, std::uint64_t generation,
                          std::uint64_t individual) const = 0;
  /// Throws GenomeError naming the gene and field when `genome` breaks a structural rule or a
  /// limit of this instance's settings.
  virtual void validate(const Genotype& genome) const = 0;
  /// Sizes of `genome` that need no development.
  virtual GenomeSize size(const Genotype& genome) const = 0;
  /// Develops `genome` (which must validate) into a body and its controller.
  virtual Creature develop(const Genotype& genome) const = 0;

  /// Whether `variation` exists for this encoding.
  virtual bool supports(Variation variation) const = 0;
  /// A mutated copy of `parent`; `parameter_rate` is the chance each parameter is perturbed
  /// (the encoding's structural rates are its own settings), or, where scalesOwnMutation(), a
  /// multiplier of the encoding's own chance. Valid under the settings.
  virtual Genotype mutate(const Genotype& parent, double parameter_rate, Rng& rng) const = 0;
  /// Whether mutate()'s `parameter_rate` multiplies a chance per gene the encoding sets itself
  /// (Walking with Dinosaurs' 1/n) rather than being the chance: breeding schemes then pass 1,
  /// or the wwd scheme's diversity multiplier.
  virtual bool scalesOwnMutation() const { return false; }
  /// A child of two parents by `variation` (crossover, graft, graft_feature, segment_crossover:
  /// `a` receives, or gives the first segment).
  /// Valid under the settings.
  virtual Genotype combine(Variation variation, const Genotype& a, const Genotype& b,
                           Rng& rng) const = 0;
  /// A varied copy of `parent` by a one-parent variation other than mutation (gene_specification,
  /// gene_split, gene_purge, branch_specification, grow_stub), with the encoding's own rates.
  /// Valid under the settings. Throws GenomeError for a variation the encoding lacks (the
  /// default: every one).
  virtual Genotype vary(Variation variation, const Genotype& parent, Rng& rng) const;
  /// The last step after any variation (the directed graph: collect unreachable nodes, unless
  /// the settings keep them).
  virtual Genotype tidy(const Genotype& genome) const { return genome; }

  /// The byte form of `data` (tag and version first).
  virtual std::vector<std::uint8_t> toBytes(const GenomeData& data) const = 0;
  /// Reads the byte form; throws InputError naming the field on bad or truncated bytes.
  virtual Genotype fromBytes(const std::uint8_t* bytes, std::size_t size) const = 0;
  /// The readable text form; exact: fromText(toText(g)) == g.
  virtual std::string toText(const Genotype& genome) const = 0;
  /// Reads the text form; throws InputError naming `source`, the line and the field.
  virtual Genotype fromText(const std::string& text, const std::string& source) const = 0;

 protected:
  /// Throws GenomeError unless `genome` is of this encoding.
  void requireOwn(const Genotype& genome) const;
};

}  // namespace cambrian
