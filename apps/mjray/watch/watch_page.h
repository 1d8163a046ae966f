#pragma once
/// The live page (apps/mjray/watch/page.html), compiled into the program by embed_page.cmake.

#include <string_view>

namespace mjray {

/// The HTML of the page, scripts and styles inline.
std::string_view watch_page();

}  // namespace mjray
