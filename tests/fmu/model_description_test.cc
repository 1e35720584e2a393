// The tyre FMU's description against FMI 2.0's rules (fmu/model_description.h): the generated
// description is valid, it names the variables as Chrono's tyre FMU does, and each rule the
// validator checks refuses a description that breaks it.
#include "modaltyre/fmu/model_description.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>

#include "modaltyre/core/errors.h"
#include "modaltyre/fmu/tyre_variables.h"

namespace modaltyre::fmu {
namespace {

ModelDescription tyre() {
  TyreDescriptionInfo info;
  info.tyre_name = "test tyre";
  info.guid = "{00000000-0000-0000-0000-000000000000}";
  info.outer_radius_m = 0.2948;
  return tyre_model_description(info);
}

ScalarVariable& named(ModelDescription& d, const std::string& name) {
  auto it = std::find_if(d.variables.begin(), d.variables.end(),
                         [&](const ScalarVariable& v) { return v.name == name; });
  EXPECT_NE(it, d.variables.end()) << name;
  return *it;
}

bool mentions(const std::vector<std::string>& problems, const std::string& text) {
  for (const std::string& p : problems)
    if (p.find(text) != std::string::npos) return true;
  return false;
}

TEST(FmuModelDescription, TyreDescriptionIsValid) {
  const ModelDescription d = tyre();
  const std::vector<std::string> problems = validate(d);
  EXPECT_TRUE(problems.empty()) << (problems.empty() ? "" : problems.front());
}

TEST(FmuModelDescription, NamesTheVariablesAsChronosTyreFmu) {
  ModelDescription d = tyre();
  std::set<std::string> inputs, outputs, parameters;
  for (const ScalarVariable& v : d.variables) {
    if (v.causality == Causality::input) inputs.insert(v.name);
    if (v.causality == Causality::output) outputs.insert(v.name);
    if (v.causality == Causality::parameter) parameters.insert(v.name);
  }
  for (const char* base :
       {"wheel_state.pos.", "wheel_state.lin_vel.", "wheel_state.ang_vel.", "terrain_normal."})
    for (const char* c : {"x", "y", "z"})
      EXPECT_TRUE(inputs.count(std::string(base) + c)) << base << c;
  for (const char* e : {"e0", "e1", "e2", "e3"})
    EXPECT_TRUE(inputs.count(std::string("wheel_state.rot.") + e));
  EXPECT_TRUE(inputs.count("terrain_height"));
  EXPECT_TRUE(inputs.count("terrain_mu"));
  for (const char* base :
       {"wheel_load.point.", "wheel_load.force.", "wheel_load.moment.", "query_point."})
    for (const char* c : {"x", "y", "z"})
      EXPECT_TRUE(outputs.count(std::string(base) + c)) << base << c;
  EXPECT_EQ(parameters, (std::set<std::string>{"step_size", "road_profile"}));
  EXPECT_EQ(named(d, "step_size").unit, "s");
  EXPECT_EQ(named(d, "wheel_load.moment.y").unit, "N.m");
  // The wheel starts touching a road at z = 0: no load before the host moves it.
  EXPECT_DOUBLE_EQ(*named(d, "wheel_state.pos.z").start, 0.2948);
}

TEST(FmuModelDescription, XmlDeclaresCoSimulationAndEveryVariableOnce) {
  const ModelDescription d = tyre();
  const std::string xml = to_xml(d);
  EXPECT_NE(xml.find("fmiVersion=\"2.0\""), std::string::npos);
  EXPECT_NE(xml.find("<CoSimulation modelIdentifier=\"ModalTyre\""), std::string::npos);
  EXPECT_EQ(xml.find("<ModelExchange"), std::string::npos);
  for (const ScalarVariable& v : d.variables) {
    const std::string tag = "name=\"" + v.name + "\"";
    const auto first = xml.find(tag);
    ASSERT_NE(first, std::string::npos) << v.name;
    EXPECT_EQ(xml.find(tag, first + 1), std::string::npos) << v.name;
  }
  // Outputs are calculated: no start attribute, listed among the initial unknowns.
  std::size_t outputs = 0;
  for (const ScalarVariable& v : d.variables) outputs += v.causality == Causality::output;
  std::size_t unknowns = 0, at = xml.find("<InitialUnknowns>");
  const std::size_t end = xml.find("</InitialUnknowns>");
  while ((at = xml.find("<Unknown ", at + 1)) < end) ++unknowns;
  EXPECT_EQ(unknowns, outputs);
}

TEST(FmuModelDescription, RefusesADuplicateValueReferenceWithinAType) {
  ModelDescription d = tyre();
  named(d, "terrain_mu").value_reference = named(d, "terrain_height").value_reference;
  EXPECT_TRUE(mentions(validate(d), "value reference"));
  EXPECT_THROW(to_xml(d), ComputationError);
  // The same number in another base type is not an alias (FMI 2.0: per type).
  ModelDescription ok = tyre();
  named(ok, "road_profile").value_reference = named(ok, "wheel_state.pos.x").value_reference;
  EXPECT_TRUE(validate(ok).empty());
}

TEST(FmuModelDescription, RefusesCausalityVariabilityPairsTheStandardForbids) {
  ModelDescription d = tyre();
  named(d, "step_size").variability = Variability::continuous;  // a continuous parameter
  EXPECT_TRUE(mentions(validate(d), "is not allowed"));
  ModelDescription e = tyre();
  named(e, "terrain_mu").variability = Variability::fixed;  // a fixed input
  EXPECT_TRUE(mentions(validate(e), "is not allowed"));
  ModelDescription f = tyre();
  named(f, "road_profile").variability = Variability::continuous;  // a continuous String
  EXPECT_TRUE(mentions(validate(f), "only a Real can be continuous"));
}

TEST(FmuModelDescription, RefusesInitialAndStartCombinationsTheStandardForbids) {
  ModelDescription d = tyre();
  named(d, "step_size").initial = Initial::calculated;  // a parameter is exact only
  EXPECT_TRUE(mentions(validate(d), "initial calculated is not allowed"));
  ModelDescription e = tyre();
  named(e, "wheel_state.pos.x").initial = Initial::exact;  // an input takes no initial
  EXPECT_TRUE(mentions(validate(e), "is not allowed"));
  ModelDescription f = tyre();
  named(f, "wheel_load.force.z").start = 0.0;  // a calculated output has no start
  EXPECT_TRUE(mentions(validate(f), "a start value is not allowed"));
  ModelDescription g = tyre();
  named(g, "terrain_mu").start.reset();  // an input needs one
  EXPECT_TRUE(mentions(validate(g), "a start value is required"));
}

TEST(FmuModelDescription, RefusesUndefinedAndMisdefinedUnits) {
  ModelDescription d = tyre();
  named(d, "wheel_load.force.x").unit = "kN";
  EXPECT_TRUE(mentions(validate(d), "not in UnitDefinitions"));
  ModelDescription e = tyre();
  for (UnitDefinition& u : e.units)
    if (u.name == "1") (*u.exponents)[1] = 1;  // "1" with a metre in it
  EXPECT_TRUE(mentions(validate(e), "do not match its name"));
  ModelDescription f = tyre();
  named(f, "terrain_height").unit.clear();
  EXPECT_TRUE(mentions(validate(f), "without a unit"));
  ModelDescription g = tyre();
  g.units.push_back(g.units.front());
  EXPECT_TRUE(mentions(validate(g), "defined twice"));
}

TEST(FmuModelDescription, RefusesNamesThatAreNotStructured) {
  ModelDescription d = tyre();
  named(d, "terrain_mu").name = "terrain mu";
  EXPECT_TRUE(mentions(validate(d), "not a structured name"));
  ModelDescription e = tyre();
  named(e, "terrain_mu").name = "terrain_height";
  EXPECT_TRUE(mentions(validate(e), "declared twice"));
}

TEST(FmuModelDescription, EscapesTextInAttributes) {
  ModelDescription d = tyre();
  d.model_name = "a \"quoted\" <tyre> & more";
  const std::string xml = to_xml(d);
  EXPECT_NE(xml.find("a &quot;quoted&quot; &lt;tyre&gt; &amp; more"), std::string::npos);
}

/// xmllint's verdict on `xml` against the FMI 2.0 schema (tests/data/fmi2_schema: the
/// standard's own XSD files): its exit status and output.
std::pair<int, std::string> schema_check(const std::string& xml, const std::string& tag) {
  const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                     ("modaltyre_md_" + std::to_string(::getpid()) + tag + ".xml");
  std::ofstream(file) << xml;
  const std::string cmd = "xmllint --noout --schema '" + std::string(MODALTYRE_SOURCE_DIR) +
                          "/tests/data/fmi2_schema/fmi2ModelDescription.xsd' '" + file.string() +
                          "' 2>&1";
  std::string out;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return {-1, "popen failed"};
  char buf[4096];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, p)) out.append(buf, n);
  const int rc = pclose(p);
  std::filesystem::remove(file);
  return {rc, out};
}

TEST(FmuModelDescription, ValidatesAgainstTheFmi2Schema) {
  const auto [rc, out] = schema_check(to_xml(tyre()), "ok");
  EXPECT_EQ(rc, 0) << out;
  EXPECT_NE(out.find("validates"), std::string::npos) << out;
  // A soil FMU's: the soil's keys as parameters, their units (one without SI exponents).
  ground::GroundSettings sand;
  sand.model = ground::GroundModel::bekker;
  sand.bekker = {0.79, 102, 5301, ground::WongUnloading{0, 5e5}};
  TyreDescriptionInfo info;
  info.tyre_name = "on sand";
  info.guid = "{00000000-0000-0000-0000-000000000001}";
  info.soil = &sand;
  const ModelDescription soil = tyre_model_description(info);
  EXPECT_TRUE(validate(soil).empty());
  const std::string xml = to_xml(soil);
  EXPECT_NE(xml.find("<Unit name=\"kN/m^(n+1)\"/>"), std::string::npos);
  EXPECT_NE(xml.find("name=\"ground.bekker.unloading.Au\""), std::string::npos);
  const auto [rc3, out3] = schema_check(xml, "soil");
  EXPECT_EQ(rc3, 0) << out3;
  // The check sees a breach: a causality the schema does not know.
  std::string broken = to_xml(tyre());
  broken.replace(broken.find("causality=\"input\""), 17, "causality=\"inlet\"");
  const auto [rc2, out2] = schema_check(broken, "broken");
  EXPECT_NE(rc2, 0) << out2;
}

TEST(FmuModelDescription, RefusesARangeThatExcludesItsStartAndDependenciesOnUnknowns) {
  ModelDescription d = tyre();
  named(d, "terrain_mu").max = 0.5;  // start 0.8
  EXPECT_TRUE(mentions(validate(d), "start value outside [min, max]"));
  ModelDescription e = tyre();
  named(e, "step_size").min = 2.0;  // min above max
  EXPECT_TRUE(mentions(validate(e), "min is not below max"));
  ModelDescription f = tyre();
  named(f, "wheel_load.force.z").dependencies = std::vector<std::string>{"wheel_load.force.x"};
  EXPECT_TRUE(mentions(validate(f), "is not a known input"));
  ModelDescription g = tyre();
  named(g, "wheel_load.force.z").initial_dependencies = std::vector<std::string>{"no.such"};
  EXPECT_TRUE(mentions(validate(g), "is not a variable"));
  // A parameter (initial exact) is a known in initialization mode, not at a step.
  ModelDescription h = tyre();
  named(h, "wheel_load.force.z").initial_dependencies = std::vector<std::string>{"step_size"};
  EXPECT_TRUE(validate(h).empty());
  named(h, "wheel_load.force.z").dependencies = std::vector<std::string>{"step_size"};
  EXPECT_TRUE(mentions(validate(h), "is not a known input"));
}

}  // namespace
}  // namespace modaltyre::fmu
