// fdhcert's help layout (a CLI11 formatter): the usage line first, then the description; an
// option's value as its type name alone; the command list shows the first line of each
// command's description.
#pragma once

#include <memory>

namespace CLI {
class FormatterBase;
}

namespace fdh::verify {

std::shared_ptr<CLI::FormatterBase> help_layout();

}  // namespace fdh::verify
