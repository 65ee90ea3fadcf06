// A job's result object (nlohmann::ordered_json, built by the job's to_json) as Python values:
// dicts in the job's key order, lists, str, int, float, bool, None. No JSON text in between;
// names keep the JSON rule's one reversible way of writing bytes that are not UTF-8
// (io/json_text.hpp json_string), so the dict equals `fdhcert ... --json` read by json.loads.
#include <nlohmann/json.hpp>

#include "bindings.hpp"
#include "fdh/io/json_text.hpp"

namespace fdh::python {

py::object python_value(const nlohmann::ordered_json& j) {
  switch (j.type()) {
    case nlohmann::ordered_json::value_t::object: {
      py::dict d;
      for (const auto& [key, value] : j.items())
        d[py::str(verify::json_string(key))] = python_value(value);
      return std::move(d);
    }
    case nlohmann::ordered_json::value_t::array: {
      py::list l;
      for (const auto& value : j) l.append(python_value(value));
      return std::move(l);
    }
    case nlohmann::ordered_json::value_t::string:
      return py::str(verify::json_string(j.get_ref<const std::string&>()));
    case nlohmann::ordered_json::value_t::boolean:
      return py::bool_(j.get<bool>());
    case nlohmann::ordered_json::value_t::number_integer:
      return py::int_(j.get<std::int64_t>());
    case nlohmann::ordered_json::value_t::number_unsigned:
      return py::int_(j.get<std::uint64_t>());
    case nlohmann::ordered_json::value_t::number_float:
      return py::float_(j.get<double>());
    default:
      return py::none();
  }
}

}  // namespace fdh::python
