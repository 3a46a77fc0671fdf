// SvgDebugDrawTest.cpp - the SVG picture writer: known points land on the pixels the fitted orthographic
// camera puts them at, and what it writes is one whole SVG document with one element per thing drawn.
#include "SvgDebugDraw.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace svg_test {

size_t countOf(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

TEST(SvgDebugDraw, ProjectsKnownPointsToTheFittedPixels) {
    // Looking along +z: x right, y up. A 2 x 2 m square fits 80 px high inside 200 x 100 with 10 px margins
    // (40 px a metre), centred: x from 60 to 140, y from 90 up to 10.
    SvgDebugDraw svg(200, 100, Vector(0, 0, 1), 10.0f);
    svg.drawLine(Vector(-1, -1, 0), Vector(1, 1, 3), 0xFF000000u);
    const SvgDebugDraw::Pixel corner = svg.project(Vector(1, 1, 0)), middle = svg.project(Vector(0, 0, -7));
    EXPECT_FLOAT_EQ(corner.x, 140.0f);
    EXPECT_FLOAT_EQ(corner.y, 10.0f);
    EXPECT_FLOAT_EQ(middle.x, 100.0f); // depth does not move a point in an orthographic picture
    EXPECT_FLOAT_EQ(middle.y, 50.0f);
    EXPECT_FLOAT_EQ(svg.project(Vector(-1, 0, 0)).x, 60.0f);
}

TEST(SvgDebugDraw, LooksDownWithZUpOnThePage) {
    SvgDebugDraw svg(100, 100, Vector(0, -1, 0), 0.0f);
    svg.drawLine(Vector(-1, 5, -1), Vector(1, 0, 1), 0xFF000000u);
    // From above in a left-handed world: +x right, +z up the page (smaller y in SVG).
    EXPECT_FLOAT_EQ(svg.project(Vector(1, 0, 1)).x, 100.0f);
    EXPECT_FLOAT_EQ(svg.project(Vector(1, 0, 1)).y, 0.0f);
    EXPECT_FLOAT_EQ(svg.project(Vector(-1, 0, -1)).y, 100.0f);
}

TEST(SvgDebugDraw, WritesOneWholeDocumentWithAnElementPerThingDrawn) {
    SvgDebugDraw svg;
    svg.drawWireBox(Vector(0, 1, 0), Vector(1, 1, 1), Matrix(1), 0xFF30C030u); // 12 lines
    svg.drawLine(Vector(0, 0, 0), Vector(0, 3, 0), 0x80FF0000u);
    svg.drawWireSphere(Vector(3, 1, 0), 1.0f, 0xFF6080FFu); // one circle: a sphere's outline
    svg.drawPoint(Vector(0, 0, 0), 0.1f, 0xFFFF2020u);
    svg.drawText(Vector(0, 2, 0), "a < b & c", 0xFF000000u);
    EXPECT_EQ(svg.shapeCount(), 16u);

    const std::string path = ::testing::TempDir() + "svg_debug_draw_test.svg";
    ASSERT_TRUE(svg.write(path));
    std::ifstream in(path, std::ios::binary);
    std::stringstream read;
    read << in.rdbuf();
    const std::string text = read.str();
    std::remove(path.c_str());
    EXPECT_EQ(text, svg.svg());
    EXPECT_EQ(text.rfind("<svg ", 0), 0u);
    ASSERT_GE(text.size(), 7u);
    EXPECT_EQ(text.substr(text.size() - 7), "</svg>\n");
    EXPECT_EQ(countOf(text, "<svg"), 1u);
    EXPECT_EQ(countOf(text, "<line "), 13u);
    EXPECT_EQ(countOf(text, "<circle "), 2u);
    EXPECT_EQ(countOf(text, "<text "), 1u);
    EXPECT_NE(text.find(">a &lt; b &amp; c</text>"), std::string::npos);
    EXPECT_NE(text.find("stroke=\"#FF0000\" stroke-opacity=\"0.50\""), std::string::npos);

    svg.clear();
    EXPECT_EQ(svg.shapeCount(), 0u);
    EXPECT_FALSE(svg.write(::testing::TempDir() + "no/such/dir/x.svg"));
}

} // namespace svg_test
