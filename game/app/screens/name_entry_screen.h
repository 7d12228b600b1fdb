#pragma once
#include <memory>
#include <string>

#include "app/screens/screen.h"

namespace polar::game {

// A new high score: three letters, "AAA" to start. Typed letters fill the places from the left
// and Backspace takes the last one back; up/down (or the pad) change the letter under the cursor
// and left/right move it; confirm on the last place (or after three letters) saves the table and
// shows it. Back keeps the score too, under the letters set so far or else the last name used, and
// shows the table: a score is never thrown away.
std::unique_ptr<Screen> makeNameEntryScreen();

// The name entry's rule, apart from drawing: for tests.
class NameEntry {
  public:
    // Applies one frame's commands; true when the name is done (confirmed on the last place).
    bool update(const Input::Commands& commands);
    const std::string& name() const { return name_; }
    // The place the cursor is on (0, 1 or 2).
    std::size_t cursor() const { return place_ < 3 ? place_ : 2; }
    // The name a score is kept under when the player leaves without finishing: the letters set so
    // far (typed, or changed with up/down), else `lastName` (else the name as shown).
    std::string keptName(const std::string& lastName) const;

  private:
    std::string name_ = "AAA";
    std::size_t place_ = 0;  // the next place a typed letter fills; 3 when all are typed
    std::size_t set_ = 0;    // how many places from the left the player has set
};

}  // namespace polar::game
