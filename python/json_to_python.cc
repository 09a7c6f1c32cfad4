#include "python/json_to_python.h"

namespace implicitfit::python {
namespace {

namespace py = pybind11;

template <typename Json>
py::object Convert(const Json& value) {
  switch (value.type()) {
    case Json::value_t::null:
      return py::none();
    case Json::value_t::boolean:
      return py::bool_(value.template get<bool>());
    case Json::value_t::number_integer:
      return py::int_(value.template get<long long>());
    case Json::value_t::number_unsigned:
      return py::int_(value.template get<unsigned long long>());
    case Json::value_t::number_float:
      return py::float_(value.template get<double>());
    case Json::value_t::string:
      return py::str(value.template get_ref<const std::string&>());
    case Json::value_t::array: {
      py::list list;
      for (const Json& item : value) list.append(Convert(item));
      return std::move(list);
    }
    case Json::value_t::object: {
      py::dict dict;
      for (auto it = value.begin(); it != value.end(); ++it)
        dict[py::str(it.key())] = Convert(it.value());
      return std::move(dict);
    }
    default:
      return py::none();  // binary and discarded values: never in our reports
  }
}

}  // namespace

py::object ToPython(const nlohmann::json& value) { return Convert(value); }
py::object ToPython(const nlohmann::ordered_json& value) { return Convert(value); }

}  // namespace implicitfit::python
