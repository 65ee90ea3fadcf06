// A job's JSON object (in memory, never as text) as the Python objects json.loads would give.
#include <nlohmann/json.hpp>

#include "bindings.hpp"

namespace fdh::python {

py::object python_object(const nlohmann::ordered_json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::null:
      return py::none();
    case nlohmann::json::value_t::boolean:
      return py::bool_(j.get<bool>());
    case nlohmann::json::value_t::number_integer:
      return py::int_(j.get<long long>());
    case nlohmann::json::value_t::number_unsigned:
      return py::int_(j.get<unsigned long long>());
    case nlohmann::json::value_t::number_float:
      return py::float_(j.get<double>());
    case nlohmann::json::value_t::string:
      return py::str(j.get_ref<const std::string&>());
    case nlohmann::json::value_t::array: {
      py::list l;
      for (const auto& e : j) l.append(python_object(e));
      return std::move(l);
    }
    case nlohmann::json::value_t::object: {
      py::dict d;
      for (const auto& [key, value] : j.items()) d[py::str(key)] = python_object(value);
      return std::move(d);
    }
    default:  // binary and discarded: never in a job's output
      throw std::logic_error("a JSON value of no Python type");
  }
}

}  // namespace fdh::python
