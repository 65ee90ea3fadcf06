#include "fdh/help/help_layout.hpp"

#include <CLI/CLI.hpp>

#include <sstream>
#include <string>

namespace fdh::verify {
namespace {

// The usage line first, then the description (as the help texts read before CLI11); the command
// list shows the first line of each command's description.
class HelpFormatter : public CLI::Formatter {
 public:
  std::string make_help(const CLI::App* app, std::string name,
                        CLI::AppFormatMode mode) const override {
    if (mode == CLI::AppFormatMode::Sub) return make_expanded(app);
    return make_usage(app, name) + "\n" + make_description(app) + make_positionals(app) +
           make_groups(app, mode) + make_subcommands(app, mode) + "\n" + make_footer(app);
  }
  // The description without the blank lines a raw string may end with.
  std::string make_description(const CLI::App* app) const override {
    std::string d = app->get_description();
    while (!d.empty() && d.back() == '\n') d.pop_back();
    return d.empty() ? d : d + "\n";
  }
  // An option's value as its type name alone (its help says the range or the choices), and
  // "..." after a positional that takes several.
  std::string make_option_opts(const CLI::Option* opt) const override {
    if (opt->get_type_size() == 0) return "";  // a flag
    if (opt->get_positional()) return opt->get_expected_max() > 1 ? " ..." : "";
    const std::string type = opt->get_type_name();
    return " " + type.substr(0, type.find(':'));
  }
  std::string make_subcommand(const CLI::App* sub) const override {
    const std::string& d = sub->get_description();
    std::ostringstream out;
    CLI::detail::format_help(out, sub->get_display_name(true), d.substr(0, d.find('\n')),
                             column_width_);
    return out.str();
  }
};

}  // namespace

std::shared_ptr<CLI::FormatterBase> help_layout() {
  return std::make_shared<HelpFormatter>();
}

}  // namespace fdh::verify
