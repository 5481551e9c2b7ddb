// Tests of the registered encodings: names, tags and text headers are distinct, lookups by name
// and by tag, genome bytes of any encoding decoded by their tag.
#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>
#include <string>

namespace cambrian {
namespace {

TEST(Encodings, NamesTagsAndHeadersAreDistinct) {
  std::set<std::string> names, tags, headers;
  for (const Encoding* encoding : encodings()) {
    names.insert(encoding->name());
    std::array<char, 4> tag = encoding->tag();  // one array: begin and end of two copies differ
    tags.insert(std::string(tag.begin(), tag.end()));
    headers.insert(encoding->textHeader());
  }
  EXPECT_EQ(names.size(), encodings().size());
  EXPECT_EQ(tags.size(), encodings().size());
  EXPECT_EQ(headers.size(), encodings().size());
  EXPECT_EQ(encodingNames().front(), "directed_graph");
}

TEST(Encodings, FoundByNameAndByTag) {
  for (const Encoding* encoding : encodings()) {
    EXPECT_EQ(&findEncoding(encoding->name()), encoding);
    EXPECT_EQ(encodingForTag(encoding->tag()), encoding);
  }
  EXPECT_EQ(encodingForTag({'N', 'O', 'N', 'E'}), nullptr);
  try {
    findEncoding("lsystem");
    FAIL() << "an unknown encoding was found";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("genome.encoding = lsystem: must be one of "
                                         "directed_graph"),
              std::string::npos)
        << e.what();
  }
}

// every encoding's random genomes decode from their bytes to the same genome, the bytes kept
TEST(Encodings, BytesOfEveryEncodingDecodeByTheirTag) {
  for (const Encoding* encoding : encodings()) {
    for (std::uint64_t i = 0; i < 20; ++i) {
      Genotype genome = encoding->random(3, 0, i);
      const std::vector<std::uint8_t>& bytes = genome.bytes();
      ASSERT_GE(bytes.size(), 8u);
      const std::array<char, 4> tag = encoding->tag();
      EXPECT_TRUE(std::equal(tag.begin(), tag.end(), bytes.begin()));
      Genotype back = decodeGenome(bytes);
      EXPECT_EQ(back.encoding().name(), encoding->name());
      EXPECT_EQ(back.bytes(), bytes);
      EXPECT_TRUE(back == genome);
      EXPECT_EQ(encoding->toText(back), encoding->toText(genome));
    }
  }
}

TEST(Encodings, BytesOfNoEncodingAreRefused) {
  const std::vector<std::uint8_t> foreign{'N', 'O', 'P', 'E', 1, 0, 0, 0};
  EXPECT_THROW(decodeGenome(foreign), InputError);
  EXPECT_THROW(decodeGenome(std::vector<std::uint8_t>{'C', 'M'}), InputError);
  EXPECT_THROW(decodeGenome(std::vector<std::uint8_t>{}), InputError);
}

}  // namespace
}  // namespace cambrian
