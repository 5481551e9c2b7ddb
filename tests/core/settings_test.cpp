// Tests of the typed settings: parsing by type, INI text out and in, rules, choices, run-only
// keys, the reader's errors.
#include "core/settings.hpp"

#include "cambrian/error.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace cambrian {
namespace {

enum class Colour : std::uint8_t { red, green };

// a schema over one variable of each type
struct Fixture {
  double real = 0.25;
  int integer = 3;
  std::uint64_t count = 7;
  std::uint64_t seed = 1;
  bool flag = false;
  std::string text = "walk";
  std::vector<std::string> list;
  Colour colour = Colour::red;
  SettingsSchema schema;

  Fixture() {
    schema.add("b.real", real, "a real").require([this] { return real > 0; }, "must be > 0");
    schema.add("b.integer", integer, "an integer");
    schema.add("a.count", count, "a count").runOnly();
    schema.addSeed("a.seed", seed, "a seed");
    schema.add("b.flag", flag, "a flag").earlierRunsUsed("true");
    schema.add("b.text", text, "a word").oneOf({"walk", "jump"});
    schema.add("b.list", list, "paths");
    schema.addChoice("b.colour", colour, {{"red", Colour::red}, {"green", Colour::green}},
                     "a colour");
  }
};

TEST(Settings, EachTypeParsesItsText) {
  Fixture f;
  f.schema.set("b.real", "1e-3");
  f.schema.set("b.integer", "-12");
  f.schema.set("a.count", "18446744073709551615");
  f.schema.set("a.seed", "42");
  f.schema.set("b.flag", "yes");
  f.schema.set("b.text", "  jump ");
  f.schema.set("b.list", "a.genome, b.genome");
  f.schema.set("b.list", "c.genome");
  f.schema.set("b.colour", "green");
  EXPECT_EQ(f.real, 1e-3);
  EXPECT_EQ(f.integer, -12);
  EXPECT_EQ(f.count, UINT64_MAX);
  EXPECT_EQ(f.seed, 42u);
  EXPECT_TRUE(f.flag);
  EXPECT_EQ(f.text, "jump");
  EXPECT_EQ(f.list, (std::vector<std::string>{"a.genome", "b.genome", "c.genome"}));
  EXPECT_EQ(f.colour, Colour::green);
}

TEST(Settings, WrongTypesAreTypeErrorsNamingKeyAndValue) {
  Fixture f;
  for (auto [key, value] : std::vector<std::pair<std::string, std::string>>{{"b.real", "fast"},
                                                                            {"b.integer", "1.5"},
                                                                            {"b.integer", "many"},
                                                                            {"a.seed", "-3"},
                                                                            {"a.seed", "1e3"},
                                                                            {"b.flag", "maybe"}}) {
    try {
      f.schema.set(key, value);
      FAIL() << key << " = " << value << " was accepted";
    } catch (const SettingTypeError& e) {
      std::string message = e.what();
      EXPECT_NE(message.find(key + " = " + value), std::string::npos) << message;
    }
  }
  // an unknown choice is a config error listing the choices
  try {
    f.schema.set("b.colour", "blue");
    FAIL() << "blue was accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("b.colour = blue: must be red or green"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(f.schema.set("b.nothing", "1"), ConfigError);
}

TEST(Settings, RulesNameTheKeyTheValueAndTheRule) {
  Fixture f;
  EXPECT_NO_THROW(f.schema.check());
  f.schema.set("b.real", "-0.5");
  try {
    f.schema.check();
    FAIL() << "a negative real passed";
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(), "b.real = -0.5: must be > 0");
  }
  f.schema.set("b.real", "1");
  f.text = "swim";
  try {
    f.schema.check();
    FAIL() << "swim passed";
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(), "b.text = swim: must be walk or jump");
  }
}

TEST(Settings, CrossChecksRunAfterTheRules) {
  Fixture f;
  f.schema.addCheck([&f] {
    if (f.integer > f.real)
      throw ConfigError("b.integer must not exceed b.real");
  });
  EXPECT_THROW(f.schema.check(), ConfigError);
  f.schema.set("b.real", "5");
  EXPECT_NO_THROW(f.schema.check());
}

TEST(Settings, IniTextIsSortedExactAndReadsBack) {
  Fixture f;
  f.schema.set("b.real", "0.1");
  f.schema.set("b.list", "x y");
  const std::string text = f.schema.iniText();
  EXPECT_EQ(text,
            "[a]\ncount = 7\nseed = 1\n\n[b]\ncolour = red\nflag = false\ninteger = 3\nlist = x "
            "y\nreal = 0.1\ntext = walk\n");
  // the defaults in the same form
  EXPECT_NE(f.schema.defaultIniText().find("real = 0.25\n"), std::string::npos);
  EXPECT_NE(f.schema.defaultIniText().find("list = \n"), std::string::npos);

  // read back into fresh variables: the same text
  Fixture g;
  g.schema.find("b.list")->reset();
  for (const IniEntry& entry : parseIni(text, "test"))
    g.schema.set(entry.key, entry.value);
  EXPECT_EQ(g.schema.iniText(), text);

  // a real is written in its shortest exact form
  f.real = 1.0 / 3.0;
  EXPECT_EQ(f.schema.find("b.real")->text(), "0.3333333333333333");
}

TEST(Settings, RunOnlyKeysAreDeclaredOnceAndLeftOutOfTheResultText) {
  Fixture f;
  EXPECT_EQ(f.schema.runOnlyKeys(), (std::set<std::string>{"a.count"}));
  const std::string without = iniTextWithout(f.schema.iniText(), f.schema.runOnlyKeys());
  EXPECT_EQ(without.find("count"), std::string::npos);
  EXPECT_NE(without.find("seed = 1"), std::string::npos);
}

// a key newer than some stored runs says what they used; the others used their defaults
TEST(Settings, KeysNewerThanStoredRunsSayWhatThoseUsed) {
  Fixture f;
  EXPECT_EQ(f.schema.earlierRunValues(), (std::map<std::string, std::string>{{"b.flag", "true"}}));
  const std::string earlier = f.schema.earlierRunsIniText();
  EXPECT_NE(earlier.find("flag = true\n"), std::string::npos) << earlier;
  EXPECT_NE(earlier.find("real = 0.25\n"), std::string::npos) << earlier;
  EXPECT_NE(f.schema.defaultIniText().find("flag = false\n"), std::string::npos);
}

TEST(Settings, ResetRestoresTheDefaults) {
  Fixture f;
  f.schema.set("b.real", "9");
  f.schema.set("b.list", "a b");
  f.schema.set("b.colour", "green");
  f.schema.reset();
  EXPECT_EQ(f.real, 0.25);
  EXPECT_TRUE(f.list.empty());
  EXPECT_EQ(f.colour, Colour::red);
}

TEST(Settings, DeclaringAKeyTwiceOrWithoutASectionIsAnError) {
  Fixture f;
  double other = 0;
  EXPECT_THROW(f.schema.add("b.real", other, "again"), Error);
  EXPECT_THROW(f.schema.add("nosection", other, "no dot"), Error);
}

TEST(Ini, ReadsSectionsCommentsAndBothSpacings) {
  std::vector<IniEntry> entries = parseIni(
      "# a comment\n[task]\nname = walk   # trailing\nevaluation_time=3\n\n ; another\n"
      "[ physics ]\ntime_step = 0.004\n",
      "x.ini");
  ASSERT_EQ(entries.size(), 3u);
  EXPECT_EQ(entries[0].key, "task.name");
  EXPECT_EQ(entries[0].value, "walk");
  EXPECT_EQ(entries[1].key, "task.evaluation_time");
  EXPECT_EQ(entries[1].value, "3");
  EXPECT_EQ(entries[1].line, 4);
  EXPECT_EQ(entries[2].key, "physics.time_step");
  EXPECT_EQ(iniValues("[a]\nb = 1\nb = 2\n").at("a.b"), "2");
}

TEST(Ini, BadLinesNameTheSourceAndTheLine) {
  for (const std::string& text :
       {std::string("[task]\njust words\n"), std::string("key = 1\n"),
        std::string("[task\nname = walk\n"), std::string("[task]\n = 3\n")}) {
    try {
      parseIni(text, "bad.ini");
      FAIL() << "accepted: " << text;
    } catch (const ConfigError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("bad.ini: line ", 0), 0u) << e.what();
    }
  }
}

TEST(Settings, SeedsAreDigitsOnly) {
  std::uint64_t value = 5;
  EXPECT_TRUE(parseSeed("18446744073709551615", value));
  EXPECT_EQ(value, UINT64_MAX);
  EXPECT_FALSE(parseSeed("18446744073709551616", value));
  EXPECT_FALSE(parseSeed("-1", value));
  EXPECT_FALSE(parseSeed("", value));
  EXPECT_FALSE(parseSeed("12a", value));
  EXPECT_EQ(value, UINT64_MAX);
}

}  // namespace
}  // namespace cambrian
