// The registration rows of every built-in: a summary for :help, the parameter lists its implementation
// binds (the forms the resolver checks calls against), and a signature text that names what they accept.
// Then the forms of the multi-form built-ins still bind as before.
#include <gtest/gtest.h>

#include <cctype>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/builtins/builtins.hpp"
#include "tests/runtime/runtime_test_support.hpp"

namespace hlr::runtime {
namespace {

using test::value;

struct Named {
  std::string name;
  const BuiltinFunction* f;
};

std::vector<Named> builtin_functions() {
  std::vector<Named> out;
  for (const std::string& name : builtins().names()) {
    const Value* v = builtins().find(name);
    if (!v->is(ValueKind::Function)) continue;  // pi
    const auto* f = std::get_if<BuiltinFunction>(&v->as_function()->body);
    if (f) out.push_back({name, f});
  }
  return out;
}

// The identifiers of a signature text: "box(min: p, max: q)" -> box, min, p, max, q.
std::set<std::string> words(std::string_view text) {
  std::set<std::string> out;
  std::string word;
  for (const char c : std::string(text) + " ") {
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '_') {
      word += c;
    } else if (!word.empty()) {
      out.insert(word);
      word.clear();
    }
  }
  return out;
}

TEST(BuiltinRows, EveryFunctionHasAOneSentenceSummary) {
  const std::vector<Named> all = builtin_functions();
  ASSERT_GT(all.size(), 60U);
  for (const Named& b : all) {
    EXPECT_FALSE(b.f->summary.empty()) << b.name;
    if (b.f->summary.empty()) continue;
    EXPECT_EQ(b.f->summary.back(), '.') << b.name << ": " << b.f->summary;
    EXPECT_EQ(b.f->summary.find('\n'), std::string::npos) << b.name;
  }
}

TEST(BuiltinRows, OnlyTheVariadicBuiltinsHaveNoForms) {
  for (const Named& b : builtin_functions()) {
    const bool variadic = b.name == "min" || b.name == "max" || b.name == "union" || b.name == "difference" ||
                          b.name == "intersection";
    EXPECT_EQ(b.f->forms.empty(), variadic) << b.name;
    std::set<const ParamList*> seen;
    for (const ParamList* form : b.f->forms) {
      ASSERT_NE(form, nullptr) << b.name;
      EXPECT_TRUE(seen.insert(form).second) << b.name << " lists one form twice";
    }
  }
}

TEST(BuiltinRows, ParameterNamesAreUniqueWithinAForm) {
  for (const Named& b : builtin_functions())
    for (const ParamList* form : b.f->forms) {
      std::set<std::string_view> names;
      for (const Param& p : *form) {
        EXPECT_FALSE(p.name.empty()) << b.name;
        EXPECT_TRUE(names.insert(p.name).second) << b.name << ": '" << p.name << "' twice";
      }
    }
}

TEST(BuiltinRows, TheSignatureNamesEveryParameterOfEveryForm) {
  for (const Named& b : builtin_functions()) {
    const std::set<std::string> shown = words(b.f->signature);
    for (const ParamList* form : b.f->forms)
      for (const Param& p : *form)
        EXPECT_TRUE(shown.count(std::string(p.name)))
            << b.name << ": '" << p.name << "' is not in \"" << b.f->signature << "\"";
  }
}

// Hints show the signature as calls: each alternative starts with the name and "(".
TEST(BuiltinRows, EverySignatureAlternativeIsACallOfTheBuiltin) {
  for (const Named& b : builtin_functions()) {
    const std::string& s = b.f->signature;
    std::size_t at = 0;
    while (true) {
      EXPECT_EQ(s.compare(at, b.name.size() + 1, b.name + "("), 0) << b.name << ": \"" << s << "\"";
      const std::size_t bar = s.find(" | ", at);
      if (bar == std::string::npos) break;
      at = bar + 3;
    }
  }
}

// A built-in without parameters has one empty form (so a resolver can say it takes no arguments).
TEST(BuiltinRows, ABuiltinWithoutParametersHasOneEmptyForm) {
  for (const Named& b : builtin_functions()) {
    const bool no_parameters = b.f->signature == b.name + "()";
    bool has_empty = false;
    for (const ParamList* form : b.f->forms) has_empty |= form->empty();
    EXPECT_EQ(has_empty, no_parameters) << b.name;
    if (no_parameters) {
      EXPECT_EQ(b.f->forms.size(), 1U) << b.name;
    }
  }
  EXPECT_EQ(value("identity() == translate(0, 0, 0)"), "true");
}

// The implementation reads a default through the same typed accessor as a given argument.
TEST(BuiltinRows, DefaultsAreOfAnAcceptedKind) {
  for (const Named& b : builtin_functions())
    for (const ParamList* form : b.f->forms)
      for (const Param& p : *form) {
        if (p.fallback.is_none()) continue;
        EXPECT_FALSE(p.required) << b.name << ": '" << p.name << "' is required but has a default";
        EXPECT_NE(p.kinds & kinds(p.fallback.kind()), KindSet{0}) << b.name << ": '" << p.name << "'";
      }
}

// ---- the forms of the multi-form built-ins still bind ----

TEST(BuiltinForms, BoxBySizesCornersOrSizeAndCentre) {
  const FrameScene scene = test::run_ok(
      "draw box(1, 2, 3)\n"
      "draw box(sx: 1, sy: 2, sz: 3)\n"
      "draw box(min: (0, 0, 0), max: (1, 2, 3))\n"
      "draw box(size: (1, 2, 3), center: (0.5, 1, 1.5))\n");
  ASSERT_EQ(scene.scene.objects.size(), 4U);
  for (std::size_t i = 1; i < 4; ++i)
    EXPECT_EQ(scene.scene.objects[i].solid->vertices, scene.scene.objects[0].solid->vertices) << i;
  EXPECT_EQ(test::first_error("draw box(min: (0, 0, 0))"), "1:6: missing argument 'max' to box()");
  EXPECT_EQ(test::first_error("draw box(1, 2)"), "1:6: missing argument 'sz' to box()");
}

TEST(BuiltinForms, TranslateByAVectorOrThreeNumbers) {
  EXPECT_EQ(value("translate((1, 2, 3)) == translate(1, 2, 3)"), "true");
  EXPECT_EQ(value("translate(v: (1, 2, 3)) == translate(x: 1, y: 2, z: 3)"), "true");
  EXPECT_EQ(value("translate((1, 2, 3))"), value("translate(1, 2, 3)"));
  EXPECT_EQ(test::first_error("let t = translate(1, 2)"), "1:9: missing argument 'z' to translate()");
}

// rotate and scale have one list each; which parameters are given picks what they do.
TEST(BuiltinForms, RotateAndScaleByTheirNamedParameters) {
  EXPECT_EQ(
      value("rotate(degrees: 90, axis: (0, 0, 1), about: (1, 0, 0)) == rotate(z: 90, about: (1, 0, 0))"),
      "true");
  EXPECT_EQ(value("rotate(x: 30, y: 40) == (rotate(x: 30) then rotate(y: 40))"), "true");
  EXPECT_EQ(value("scale(sx: 2) == scale(2, 2, 2)"), "true");
  EXPECT_EQ(value("scale(sx: 1, sy: 2, sz: 3, about: (1, 1, 1)) == scale(1, 2, 3, about: (1, 1, 1))"),
            "true");
}

}  // namespace
}  // namespace hlr::runtime
