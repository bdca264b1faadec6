// mkillum's input stream: comments, commands and primitives as written, and one test per
// kind of bad primitive with its file and line.
#include "illum/illum_input.h"

#include <gtest/gtest.h>

#include <vector>

namespace rp::illum {
namespace {

std::vector<InputItem> readAll(const std::string& text) {
    InputReader r(text, "in.rad");
    std::vector<InputItem> items;
    for (InputItem i = r.next(); i.kind != InputItem::Kind::kEnd; i = r.next()) items.push_back(i);
    return items;
}

std::string errorOf(const std::string& text) {
    try {
        readAll(text);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

TEST(IllumInput, ItemsInOrder) {
    const auto items = readAll(
        "# a comment\n"
        "#@mkillum i=glass\n"
        "!genbox glass box 1 \\\n 2 3\n"
        "void glass glass\n0\n0\n3 .9 .9 .9\n"
        "\n  glass polygon 'my pane'\n0\n0\n9 0 0 0  1 0 0  1 1 0\n"
        "void alias other glass\n"
        "# last, no newline");
    ASSERT_EQ(items.size(), 7u);
    EXPECT_EQ(items[0].kind, InputItem::Kind::kComment);
    EXPECT_EQ(items[0].text, "# a comment\n");
    EXPECT_EQ(items[1].text, "#@mkillum i=glass\n");
    EXPECT_EQ(items[1].loc.line, 2);
    EXPECT_EQ(items[2].kind, InputItem::Kind::kCommand);
    EXPECT_EQ(items[2].text, "genbox glass box 1  2 3");  // continued as the shell would
    const InputObject& m = items[3].object;
    EXPECT_EQ(m.modifier, "void");
    EXPECT_EQ(m.type, PrimType::Glass);
    EXPECT_EQ(m.rargs, (std::vector<double>{.9, .9, .9}));
    EXPECT_EQ(items[3].loc.line, 5);
    const InputObject& p = items[4].object;
    EXPECT_EQ(p.typeName, "polygon");
    EXPECT_EQ(p.name, "my pane");
    EXPECT_EQ(p.rargs.size(), 9u);
    EXPECT_EQ(p.loc.str(), "in.rad:10");
    EXPECT_TRUE(items[5].object.isAlias());
    EXPECT_EQ(items[5].object.name, "other");
    EXPECT_EQ(items[5].object.aliasOf, "glass");
    EXPECT_EQ(items[6].text, "# last, no newline");
}

TEST(IllumInput, StringArgumentsKept) {
    const auto items =
        readAll("void brightdata d\n5 noneg a.dat illum.cal il_alth il_azih\n0\n0\n");
    ASSERT_EQ(items.size(), 1u);
    EXPECT_EQ(items[0].object.sargs,
              (std::vector<std::string>{"noneg", "a.dat", "illum.cal", "il_alth", "il_azih"}));
}

TEST(IllumInput, BadPrimitives) {
    EXPECT_EQ(errorOf("\nvoid plastc p\n0\n0\n5 1 1 1 0 0\n"), "in.rad:2: unknown type 'plastc'");
    EXPECT_NE(errorOf("void plastic p\n0\n1 7\n5 1 1 1 0 0\n").find("integer arguments"),
              std::string::npos);
    EXPECT_EQ(errorOf("void plastic p\n0\n0\n5 1 1 x 0 0\n"),
              "in.rad:4: plastic 'p': bad real argument 'x'");
    EXPECT_EQ(errorOf("void plastic p\n0\n0\nfive\n"),
              "in.rad:4: plastic 'p': expected the number of real arguments, got 'five'");
    EXPECT_NE(errorOf("void plastic p\n0\n0\n5 1 1").find("in.rad:1: unexpected end of input"),
              std::string::npos);
}

}  // namespace
}  // namespace rp::illum
