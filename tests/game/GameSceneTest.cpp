// GameSceneTest.cpp - a game's own scenes: registered with an explicit call from this file, found, listed and
// run through the game's own runScene; bad names refused; where --csv puts each scene's file; a CSV that
// cannot be written is a bad argument.
#include "GameTestSupport.h"

#include "CsvLog.h"

using namespace game_test;

TEST(GameScenes, ARegisteredSceneRunsThroughTheGamesPath) {
    const SceneSpec* tower = findScene("tower");
    const size_t before = allScenes().size();
    ASSERT_EQ(findScene("falling"), nullptr);
    ASSERT_TRUE(registerScene({"falling", "a ball falling (named: ball)", buildDrop, nullptr}));
    const SceneSpec* falling = findScene("falling");
    ASSERT_NE(falling, nullptr);
    EXPECT_EQ(allScenes().size(), before + 1);
    EXPECT_EQ(&allScenes().back(), falling); // listed after the others (--list, --scene all)
    EXPECT_EQ(findScene("tower"), tower);    // registering moves no scene a game holds
    GameOptions o;
    o.frames = 70;
    o.track = {"ball"};
    o.out = std::tmpfile();
    EXPECT_EQ(runScene(*falling, o), RUN_OK);
    const std::string text = readBack(o.out);
    std::fclose(o.out);
    EXPECT_EQ(text.rfind("scene falling: a ball falling (named: ball); 1 bodies\n", 0), 0u) << text;
    EXPECT_NE(text.find("\n  track ball "), std::string::npos) << text; // its World::name reached the game
    EXPECT_NE(text.find("\nOK falling\n"), std::string::npos) << text;
}

TEST(GameScenes, BadOrTakenNamesAreRefused) {
    auto build = [](World& w) { w.ground(); };
    const size_t before = allScenes().size();
    EXPECT_FALSE(registerScene({"tower", "taken", build, nullptr}));
    EXPECT_FALSE(registerScene({"all", "means every scene", build, nullptr}));
    EXPECT_FALSE(registerScene({"", "empty", build, nullptr}));
    EXPECT_FALSE(registerScene({nullptr, "none", build, nullptr}));
    EXPECT_FALSE(registerScene({"two words", "a space", build, nullptr}));
    EXPECT_FALSE(registerScene({"a,b", "a comma (CSV)", build, nullptr}));
    EXPECT_FALSE(registerScene({"a/b", "a slash (file names)", build, nullptr}));
    EXPECT_FALSE(registerScene({"nobuild", "no builder", nullptr, nullptr}));
    EXPECT_EQ(allScenes().size(), before);
    EXPECT_TRUE(registerScene({"empty", "a floor", build, nullptr}));
    EXPECT_FALSE(registerScene({"empty", "again", build, nullptr}));
}

TEST(GameScenes, CsvFileOfEachSceneOfAll) {
    EXPECT_EQ(csvPathFor("runs.csv", "tower"), "runs-tower.csv");
    EXPECT_EQ(csvPathFor("out/runs", "tower"), "out/runs-tower.csv");
    EXPECT_EQ(csvPathFor("out/", "tower"), "out/-tower.csv");
}

TEST(GameScenes, ACsvThatCannotBeWrittenIsABadArgumentAndRunsNothing) {
    GameOptions o;
    o.frames = 10;
    o.csv = "/nonexistent-dir/x.csv";
    o.out = std::tmpfile();
    o.err = std::tmpfile();
    EXPECT_EQ(runScene(*findScene("tower"), o), RUN_BAD_ARGUMENTS);
    EXPECT_EQ(readBack(o.out), "");
    EXPECT_EQ(readBack(o.err), "ReferenceGame: cannot write /nonexistent-dir/x.csv\n");
    std::fclose(o.out);
    std::fclose(o.err);
}

TEST(GameScenes, ATrackedNameTheSceneLacksIsToldAndSkipped) {
    GameOptions o;
    o.frames = 5;
    o.track = {"nosuch", "top"};
    o.out = std::tmpfile();
    o.err = std::tmpfile();
    EXPECT_EQ(runScene(*findScene("tower"), o), RUN_OK);
    EXPECT_EQ(readBack(o.err),
              "--track: scene tower has no body 'nosuch' (named: bottom top; or an index below 10)\n");
    const std::string text = readBack(o.out);
    EXPECT_NE(text.find("  track top "), std::string::npos) << text;
    EXPECT_EQ(text.find("nosuch"), std::string::npos) << text;
    std::fclose(o.out);
    std::fclose(o.err);
}
