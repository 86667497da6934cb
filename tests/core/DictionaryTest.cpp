#include "passageMesh/core/Dictionary.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "../TestFiles.hpp"

#include "passageMesh/core/InputError.hpp"

using namespace passageMesh;

namespace {
std::filesystem::path writeTemp(const std::string& name, const std::string& content) {
  return testData::writeTempFile("passageMeshDictionaryTest", name, content);
}
}  // namespace

TEST(Dictionary, ReadsNumbersAndLengthsInChords) {
  const auto file = writeTemp("a.xml",
                              "<passageDict>\n  <pitch>0.85c</pitch>\n  <nO>30000</nO>\n"
                              "  <xIn> 0.01 </xIn>\n</passageDict>\n");
  const auto d = Dictionary::read(file, "passageDict", {"pitch", "nO", "xIn", "xOut"});
  EXPECT_DOUBLE_EQ(d.length("pitch", 2.0), 1.7);
  EXPECT_DOUBLE_EQ(d.length("xIn", 2.0), 0.01);
  EXPECT_EQ(d.integer("nO"), 30000);
  EXPECT_FALSE(d.has("xOut"));
  EXPECT_EQ(d.line("nO"), 3);
}

TEST(Dictionary, UnknownKeyIsAnErrorNamingKeyFileAndLine) {
  const auto file = writeTemp("b.xml", "<passageDict>\n<pitch>1</pitch>\n<pich>2</pich>\n</passageDict>");
  try {
    Dictionary::read(file, "passageDict", {"pitch"});
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("b.xml:3"), std::string::npos) << what;
    EXPECT_NE(what.find("pich"), std::string::npos) << what;
  }
}

TEST(Dictionary, MalformedXmlWrongRootAndBadNumbersAreErrors) {
  EXPECT_THROW(Dictionary::read(writeTemp("c.xml", "<passageDict><pitch>1</passageDict>"),
                                "passageDict", {"pitch"}),
               InputError);
  EXPECT_THROW(Dictionary::read(writeTemp("d.xml", "<meshDict></meshDict>"), "passageDict", {}),
               InputError);
  EXPECT_THROW(Dictionary::read(writeTemp("missing.xml", "") / "nothing", "passageDict", {}),
               InputError);
  const auto d = Dictionary::read(
      writeTemp("e.xml", "<passageDict><pitch>nan</pitch><nO>3.5</nO><xIn>1e400</xIn></passageDict>"),
      "passageDict", {"pitch", "nO", "xIn"});
  EXPECT_THROW(d.scalar("pitch"), InputError);
  EXPECT_THROW(d.integer("nO"), InputError);
  EXPECT_THROW(d.scalar("xIn"), InputError);
  EXPECT_THROW(d.scalar("absent"), InputError);
}

TEST(Dictionary, WritesAndReadsBackExactlyWithSections) {
  Dictionary d("bladeParameters");
  d.set("chord", 0.1 + 1e-17);
  d.set("name", std::string("LS89"));
  d.addSection("fitReport").set("meanDeviation", 1.0 / 3.0);
  const auto file = writeTemp("f.xml", "");
  d.write(file);
  const auto back = Dictionary::read(file, "bladeParameters", {"chord", "name"}, {"fitReport"});
  EXPECT_EQ(back.scalar("chord"), 0.1 + 1e-17);
  EXPECT_EQ(back.text("name"), "LS89");
  EXPECT_EQ(back.section("fitReport").scalar("meanDeviation"), 1.0 / 3.0);
}

// The one number reader of every dictionary and point file: the whole text one finite
// number, or refused.
TEST(Dictionary, ParseFiniteDoubleTakesOnlyAWholeFiniteNumber) {
  double v = 0;
  EXPECT_TRUE(parseFiniteDouble("1.5", v));
  EXPECT_EQ(v, 1.5);
  EXPECT_TRUE(parseFiniteDouble("-2e-3", v));
  EXPECT_EQ(v, -2e-3);
  for (const char* bad : {"", "1.5x", "x1", "nan", "NaN", "inf", "-inf", "1e400", "1.5 2", "--1"}) {
    v = 7;
    EXPECT_FALSE(parseFiniteDouble(bad, v)) << "'" << bad << "' read as " << v;
  }
}

// A section's keys are checked by its reader: an unknown key and a missing required key
// are InputErrors naming the key (and the keys allowed).
TEST(Dictionary, CheckKeysAndRequireNameTheKey) {
  Dictionary d("policyTrainDict", "case/system/policyTrainDict.xml");
  d.set("episodes", 10.0);
  d.set("epsiodes", 12.0);
  EXPECT_NO_THROW(d.checkKeys({"episodes", "epsiodes"}));
  try {
    d.checkKeys({"episodes", "seed"});
    ADD_FAILURE() << "an unknown key was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("epsiodes"), std::string::npos) << what;
    EXPECT_NE(what.find("seed"), std::string::npos) << what;  // the keys allowed
  }
  EXPECT_NO_THROW(d.require({"episodes"}));
  try {
    d.require({"episodes", "seed"});
    ADD_FAILURE() << "a missing key was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("seed"), std::string::npos) << e.what();
  }
}
