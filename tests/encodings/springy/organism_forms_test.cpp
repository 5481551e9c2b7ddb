// The organism's text and byte forms: exact round trips, a file a person writes by hand, and
// refusals that name the file, the line and the field.
#include "encodings/springy/organism_forms.hpp"

#include "cambrian/error.hpp"

#include "encodings/springy/organisms.hpp"
#include "encodings/springy/rules.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace cambrian::springy {
namespace {

std::string textFailure(const std::string& text) {
  try {
    parseOrganismText(text, "hand.organism");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string bytesFailure(const std::vector<std::uint8_t>& bytes) {
  try {
    organismFromBytes(bytes.data(), bytes.size());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

Organism withOddNumbers() {
  Organism o = test::screenshotMuscle();
  o.nodes[0].position = {-0.0, 1.0 / 3, 1e-300};
  o.nodes[1].mass = 2.5;
  o.tube_diameter = 0.1;
  o.tubes[0].muscle.first_move = FirstMove::shorten;
  return o;
}

TEST(OrganismForms, TextAndBytesRoundTripExactly) {
  for (const Organism& o : {test::pyramid(), test::screenshotMuscle(), withOddNumbers()}) {
    const std::string text = organismToText(o);
    EXPECT_EQ(parseOrganismText(text, "t"), o) << text;
    const std::vector<std::uint8_t> bytes = organismToBytes(o);
    EXPECT_EQ(organismFromBytes(bytes.data(), bytes.size()), o);
    EXPECT_EQ(organismToBytes(organismFromBytes(bytes.data(), bytes.size())), bytes);
  }
  // a -0 coordinate keeps its sign
  const Organism odd = withOddNumbers();
  const Organism back = parseOrganismText(organismToText(odd), "t");
  EXPECT_TRUE(std::signbit(back.nodes[0].position.x));
}

// what a person writes: comments, defaults (the thesis' node diameter and mass, tube diameter),
// a muscle without parameters resting at its initial length
TEST(OrganismForms, APersonWritesOneByHand) {
  const Organism o = parseOrganismText(R"(cambrian-springy 1
# a pyramid
node a   0   0     0.1
node b   1   0     0.1
node c   0.5 0.866 0.1   diameter 0.25 mass 2
node top 0.5 0.289 0.9
rod ab a b
rod bc b c
rod ca c a
muscle ma top a   rest 0.9 amplitude 0.1 frequency 1 first shorten
muscle mb top b
muscle mc top c   rest 0.9 amplitude 0.1 frequency 1
end
)",
                                       "pyramid.organism");
  ASSERT_EQ(o.nodes.size(), 4u);
  ASSERT_EQ(o.tubes.size(), 6u);
  EXPECT_EQ(o.tube_diameter, kTubeDiameter);
  EXPECT_EQ(o.nodes[0].diameter, kNodeDiameter);
  EXPECT_EQ(o.nodes[2].diameter, 0.25);
  EXPECT_EQ(o.nodes[2].mass, 2);
  EXPECT_EQ(o.tubes[3].muscle.first_move, FirstMove::shorten);
  EXPECT_EQ(o.tubes[5].muscle.first_move, FirstMove::lengthen);
  EXPECT_EQ(o.tubes[4].muscle.amplitude, 0);
  EXPECT_EQ(o.tubes[4].muscle.rest_length, initialLength(o, o.tubes[4]));
  EXPECT_NO_THROW(checkOrganism(o, MuscleLimits{}));
}

TEST(OrganismForms, BadTextIsRefusedNamingTheLineAndField) {
  const std::string head = "cambrian-springy 1\nnode a 0 0 0.1\nnode b 1 0 0.1\n";
  EXPECT_EQ(textFailure(head + "rod r a c\nend\n"),
            "hand.organism:4: rod 'r': no node named 'c' before this line");
  EXPECT_EQ(textFailure(head + "muscle m a b rest x\nend\n"),
            "hand.organism:4: muscle 'm': expected a number for 'rest', got 'x'");
  EXPECT_EQ(textFailure(head + "muscle m a b first sideways\nend\n"),
            "hand.organism:4: muscle 'm': unknown value 'sideways' for 'first' (one of: "
            "shorten, lengthen)");
  EXPECT_EQ(textFailure(head + "muscle m a b speed 2\nend\n"),
            "hand.organism:4: muscle 'm': unknown muscle field 'speed' (one of: rest, "
            "amplitude, frequency, first)");
  EXPECT_EQ(textFailure(head + "node a 2 0 0\nend\n"),
            "hand.organism:4: node 'a': a node of this name comes before");
  EXPECT_EQ(textFailure(head + "rod r a b\nrod r b a\nend\n"),
            "hand.organism:5: rod 'r': a rod or muscle of this name comes before");
  EXPECT_EQ(textFailure(head + "spring s a b\nend\n"),
            "hand.organism:4: unknown statement 'spring' (one of: tube_diameter, node, rod, "
            "muscle, end)");
  EXPECT_EQ(textFailure(head + "rod r a b"), "hand.organism: no `end` line: the file is cut short");
  EXPECT_EQ(textFailure(head + "end\nrod r a b\n"),
            "hand.organism:5: unexpected 'rod' after `end`");
  EXPECT_EQ(textFailure("cambrian-springy 2\nend\n"),
            "hand.organism:1: format version 2 is newer than this cambrian (1)");
  EXPECT_EQ(textFailure("cambrian-genome 2\n"),
            "hand.organism:1: expected the header 'cambrian-springy 1', got 'cambrian-genome'");
  EXPECT_EQ(textFailure(head + std::string("rod r\0x a b\nend\n", 16)),
            "hand.organism:4: a rod's name is one word of printable characters");
  EXPECT_EQ(textFailure("# nothing\n"),
            "hand.organism: empty (expected the header 'cambrian-springy 1')");
}

TEST(OrganismForms, BadBytesAreRefusedNamingTheField) {
  const std::vector<std::uint8_t> good = organismToBytes(test::pyramid());
  EXPECT_NE(bytesFailure({good.begin(), good.end() - 3}).find("truncated"), std::string::npos);
  std::vector<std::uint8_t> bytes = good;
  bytes[3] = 'G';
  EXPECT_EQ(bytesFailure(bytes), "springy organism bytes: not a springy organism (bad magic)");
  bytes = good;
  bytes[4] = 7;
  EXPECT_NE(bytesFailure(bytes).find("format version 7"), std::string::npos);
  bytes = good;
  bytes.push_back(0);
  EXPECT_NE(bytesFailure(bytes).find("end"), std::string::npos) << bytesFailure(bytes);
  // a tube to a node that does not exist
  Organism o = test::screenshotMuscle();
  o.tubes[0].b = 1;
  bytes = organismToBytes(o);
  const std::size_t b_at = bytes.size() - (8 * 3 + 1) - 1 - 4;  // the second node index
  bytes[b_at] = 5;
  EXPECT_NE(bytesFailure(bytes).find("tube 0 joins node 5 of 2"), std::string::npos)
      << bytesFailure(bytes);
  // a name the text form cannot write, a name twice
  o = test::screenshotMuscle();
  o.nodes[0].name = "two words";
  EXPECT_NE(bytesFailure(organismToBytes(o)).find("node 0: its name cannot be written"),
            std::string::npos);
  o = test::screenshotMuscle();
  o.nodes[1].name = "left";
  EXPECT_NE(bytesFailure(organismToBytes(o)).find("two nodes are named 'left'"), std::string::npos);
}

}  // namespace
}  // namespace cambrian::springy
