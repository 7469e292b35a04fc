// Text for XML reports (JUnit): escaped for an attribute or element, with whatever XML 1.0
// cannot hold (control bytes, bytes that are not UTF-8, U+FFFE/F) replaced by U+FFFD.
#pragma once

#include <string>

namespace sweetspot {

std::string xml_escape(const std::string& text);

}  // namespace sweetspot
