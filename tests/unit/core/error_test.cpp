// What reaches a terminal of a message: control characters, C1 controls and bidirectional
// overrides (whole UTF-8 characters) and stray bytes are escaped; other text stays as it is.

#include "mjray/core/error.h"

#include <gtest/gtest.h>

namespace mjray {
namespace {

TEST(EscapeControlCharacters, CommandsAreEscapedAndTextStays) {
  EXPECT_EQ(escape_control_characters("plain text, é ü 中", true), "plain text, é ü 中");
  EXPECT_EQ(escape_control_characters("a\x1b[2Jb\x07", true), "a\\027[2Jb\\007");
  EXPECT_EQ(escape_control_characters("line\n\tnext", true), "line\n\tnext");
  EXPECT_EQ(escape_control_characters("line\n\tnext\\", false), "line\\n\\tnext\\\\");
  // U+009B (CSI) as UTF-8, a lone 8-bit CSI byte, U+202E (right-to-left override), and a byte
  // that starts no character.
  EXPECT_EQ(escape_control_characters("x\xc2\x9by", true), "x\\194\\155y");
  EXPECT_EQ(escape_control_characters("x\x9by", true), "x\\155y");
  EXPECT_EQ(escape_control_characters("x\xe2\x80\xaey", true), "x\\226\\128\\174y");
  EXPECT_EQ(escape_control_characters("x\xffy\xc3", true), "x\\255y\\195");
  // The character after a C1 control is its own: "\x9b" then "1".
  EXPECT_EQ(escape_control_characters("\xc2\x9b" "1", true), "\\194\\155" "1");
}

}  // namespace
}  // namespace mjray
