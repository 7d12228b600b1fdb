// The one menu widget: keys, pad and mouse move one focus; a click activates the row under it; the
// wheel scrolls a long list with the focus kept in view; disabled items are skipped. And the name
// entry's rule: typed letters, Backspace, up/down, confirm.
#include "app/screens/widgets/menu.h"

#include <gtest/gtest.h>

#include "app/screens/name_entry_screen.h"

namespace polar::game {
namespace {

Input::Commands commands(void (*set)(Input::Commands&)) {
    Input::Commands c;
    set(c);
    return c;
}

std::vector<Menu::Item> items(int n) {
    std::vector<Menu::Item> out;
    for (int i = 0; i < n; ++i) out.push_back({"ITEM " + std::to_string(i), "", true});
    return out;
}

TEST(Menu, KeysAndPadMoveOneFocusAndWrap) {
    Menu menu(items(3), Menu::Layout{320, 100, 200, 20, 2, 8});
    EXPECT_EQ(menu.focus(), 0u);
    menu.update(commands([](Input::Commands& c) { c.down = true; }));
    EXPECT_EQ(menu.focus(), 1u);
    menu.update(commands([](Input::Commands& c) { c.up = true; }));
    menu.update(commands([](Input::Commands& c) { c.up = true; }));
    EXPECT_EQ(menu.focus(), 2u) << "up from the first wraps to the last";
    const Menu::Result chosen = menu.update(commands([](Input::Commands& c) { c.confirm = true; }));
    EXPECT_EQ(chosen.action, Menu::Action::Activate);
    EXPECT_EQ(chosen.item, 2u);
    EXPECT_EQ(menu.update(commands([](Input::Commands& c) { c.left = true; })).action,
              Menu::Action::Decrease);
    EXPECT_EQ(menu.update(commands([](Input::Commands& c) { c.right = true; })).action,
              Menu::Action::Increase);
    EXPECT_EQ(menu.update(Input::Commands{}).action, Menu::Action::None);
}

TEST(Menu, ThePointerFocusesAndAClickActivatesTheRowUnderIt) {
    Menu menu(items(3), Menu::Layout{320, 100, 200, 20, 2, 8});
    ASSERT_EQ(menu.rowRect(1), (PixelRect{220, 120, 200, 20}));
    Input::Commands hover;
    hover.pointer = Vec2(300.5, 130.5);
    EXPECT_EQ(menu.update(hover).action, Menu::Action::None);
    EXPECT_EQ(menu.focus(), 1u);
    Input::Commands outside;
    outside.pointer = Vec2(10.5, 130.5);
    menu.update(outside);
    EXPECT_EQ(menu.focus(), 1u) << "off the rows the focus stays";
    Input::Commands click;
    click.click = Vec2(300.5, 145.5);
    const Menu::Result chosen = menu.update(click);
    EXPECT_EQ(chosen.action, Menu::Action::Activate);
    EXPECT_EQ(chosen.item, 2u);
    click.click = Vec2(300.5, 20.5);
    EXPECT_EQ(menu.update(click).action, Menu::Action::None) << "a click beside the menu does nothing";
}

TEST(Menu, TheWheelScrollsAndTheFocusStaysInView) {
    Menu menu(items(10), Menu::Layout{320, 100, 200, 20, 2, 4});
    EXPECT_FALSE(menu.rowRect(4));
    Input::Commands wheel;
    wheel.wheel = -3;  // towards the player: down the list
    menu.update(wheel);
    EXPECT_EQ(menu.scroll(), 3u);
    EXPECT_EQ(menu.focus(), 3u) << "the focus moved into view";
    wheel.wheel = -100;
    menu.update(wheel);
    EXPECT_EQ(menu.scroll(), 6u) << "no further than the last row";
    ASSERT_TRUE(menu.rowRect(9));
    wheel.wheel = 0.2;  // a touchpad's fraction still moves one row
    menu.update(wheel);
    EXPECT_EQ(menu.scroll(), 5u);
    for (int i = 0; i < 7; ++i) menu.update(commands([](Input::Commands& c) { c.up = true; }));
    EXPECT_EQ(menu.focus(), 9u) << "wrapped round to the last";
    EXPECT_EQ(menu.scroll(), 6u) << "and scrolled to show it";
}

TEST(Menu, DisabledItemsAreSkipped) {
    std::vector<Menu::Item> list = items(3);
    list[1].enabled = false;
    Menu menu(list, Menu::Layout{320, 100, 200, 20, 2, 8});
    menu.update(commands([](Input::Commands& c) { c.down = true; }));
    EXPECT_EQ(menu.focus(), 2u);
    Input::Commands click;
    click.click = Vec2(300.5, 125.5);
    EXPECT_EQ(menu.update(click).action, Menu::Action::None);
}

TEST(NameEntry, TypedLettersBackspaceAndConfirm) {
    NameEntry entry;
    Input::Commands typed;
    typed.text = "bo";
    typed.down = true;  // 'S'/'W' also arrive as keys: a frame that typed takes letters only
    EXPECT_FALSE(entry.update(typed));
    EXPECT_EQ(entry.name(), "BOA");
    EXPECT_EQ(entry.cursor(), 2u);
    Input::Commands erase;
    erase.erase = true;
    entry.update(erase);
    EXPECT_EQ(entry.name(), "BAA");
    EXPECT_EQ(entry.cursor(), 1u);
    typed = Input::Commands{};
    typed.text = "ob7!";  // only letters count
    entry.update(typed);
    EXPECT_EQ(entry.name(), "BOB");
    Input::Commands confirm;
    confirm.confirm = true;
    EXPECT_TRUE(entry.update(confirm)) << "three letters typed: confirm saves";
}

TEST(NameEntry, UpDownAndConfirmStepThroughThePlaces) {
    NameEntry entry;
    Input::Commands up;
    up.up = true;
    Input::Commands down;
    down.down = true;
    Input::Commands confirm;
    confirm.confirm = true;
    entry.update(down);
    EXPECT_EQ(entry.name(), "ZAA");
    EXPECT_FALSE(entry.update(confirm));
    entry.update(up);
    EXPECT_FALSE(entry.update(confirm));
    EXPECT_TRUE(entry.update(confirm));
    EXPECT_EQ(entry.name(), "ZBA");
}

}  // namespace
}  // namespace polar::game
