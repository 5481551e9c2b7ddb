#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"

#include "encodings/directed_graph/encoding.hpp"
#include "encodings/directed_graph/genome.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace cambrian::graph {
namespace {

namespace fs = std::filesystem;

// a fresh folder for this test's files
fs::path scratch(const std::string& name) {
  fs::path dir = fs::path(CAMBRIAN_BINARY_DIR) / "test_genome_file" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// the message of the InputError that reading `path` throws, or ""
std::string failure(const std::string& path) {
  try {
    readGenomeFile(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(GenomeFile, WriteThenReadText) {
  fs::path dir = scratch("text");
  std::string path = (dir / "a.genome").string();
  Genome genome = randomGenome(GenomeLimits{}, 61, 0, 3);
  writeGenomeFile(path, makeGenotype(genome));
  EXPECT_EQ(graphGenome(readGenomeFile(path)), genome);
  // overwriting replaces it and leaves no temporary behind
  Genome other = randomGenome(GenomeLimits{}, 61, 0, 4);
  writeGenomeFile(path, makeGenotype(other));
  EXPECT_EQ(graphGenome(readGenomeFile(path)), other);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(GenomeFile, ReadsBinary) {
  fs::path dir = scratch("binary");
  std::string path = (dir / "a.cmbg").string();
  Genome genome = randomGenome(GenomeLimits{}, 61, 0, 5);
  std::vector<std::uint8_t> bytes = serializeGenome(genome);
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
  EXPECT_EQ(graphGenome(readGenomeFile(path)), genome);
  // a truncated binary file names the path and the field
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(bytes.data()), 20);
  std::string message = failure(path);
  EXPECT_EQ(message.rfind(path + ": genome bytes: truncated in", 0), 0u) << message;
}

TEST(GenomeFile, ErrorsNameThePath) {
  fs::path dir = scratch("errors");
  std::string missing = (dir / "missing.genome").string();
  EXPECT_EQ(failure(missing),
            missing + ": the genome file cannot be opened (No such file or directory)");
  EXPECT_EQ(failure(dir.string()), dir.string() + ": the genome file is a directory, not a file");
  std::string bad = (dir / "bad.genome").string();
  std::ofstream(bad) << "cambrian-genome 1\nnode 0 density heavy\n";
  EXPECT_EQ(failure(bad), bad + ":2: node 0: expected a number for 'density', got 'heavy'");
}

TEST(GenomeFile, WriteToMissingFolderThrows) {
  fs::path dir = scratch("nowhere");
  EXPECT_THROW(writeGenomeFile((dir / "no" / "such" / "a.genome").string(), makeGenotype(Genome{})),
               Error);
}

// the hand-written creatures parse, validate and have the documented structure
TEST(GenomeFile, CreatureFiles) {
  const std::string folder = std::string(CAMBRIAN_SOURCE_DIR) + "/jobs/creatures/";
  GenomeLimits limits;
  limits.max_recursive_limit = 6;  // snake.genome repeats its segment six times

  Genome single = graphGenome(readGenomeFile(folder + "single_block.genome"));
  validateGenome(single, GenomeLimits{});
  EXPECT_EQ(single.nodes.size(), 1u);
  EXPECT_TRUE(single.connections.empty());

  Genome pole = graphGenome(readGenomeFile(folder + "pole.genome"));
  validateGenome(pole, GenomeLimits{});
  ASSERT_EQ(pole.nodes.size(), 2u);
  ASSERT_EQ(pole.connections.size(), 1u);
  EXPECT_EQ(pole.nodes[1].joint_type, JointType::revolute);
  EXPECT_EQ(pole.nodes[1].neurons[0].function, NeuronFunction::oscillate_wave);

  Genome walker = graphGenome(readGenomeFile(folder + "walker4.genome"));
  validateGenome(walker, GenomeLimits{});
  ASSERT_EQ(walker.nodes.size(), 3u);
  ASSERT_EQ(walker.connections.size(), 2u);
  EXPECT_EQ(walker.connections[0].reflection, 2);  // y: a left/right pair
  EXPECT_EQ(walker.connections[1].reflection, 2);
  EXPECT_EQ(walker.nodes[1].effectors.size(),
            static_cast<std::size_t>(degreesOfFreedom(walker.nodes[1].joint_type)));

  Genome snake = graphGenome(readGenomeFile(folder + "snake.genome"));
  validateGenome(snake, limits);
  ASSERT_EQ(snake.nodes.size(), 1u);
  ASSERT_EQ(snake.connections.size(), 1u);
  EXPECT_EQ(snake.nodes[0].recursive_limit, 6);
  EXPECT_EQ(snake.connections[0].from, 0);
  EXPECT_EQ(snake.connections[0].to, 0);
  EXPECT_EQ(snake.connections[0].position, (Vec3{1, 0, 0}));

  // each file also round-trips through the canonical text
  for (const Genome* g : {&single, &pole, &walker, &snake}) {
    EXPECT_EQ(parseGenomeText(genomeToText(*g)), *g);
  }
}

}  // namespace
}  // namespace cambrian::graph
