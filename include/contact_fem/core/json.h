// A small ordered JSON value for summary.json (keys keep insertion order).
#ifndef contact_fem_json_h
#define contact_fem_json_h

#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace contact_fem
{
  /// An ordered JSON value: null, bool, number, string, array or object.
  class Json
  {
  public:
    Json();
    Json(double value);
    Json(int value);
    Json(unsigned int value);
    Json(bool value);
    Json(const std::string &value);
    Json(const char *value);

    static Json
    object();
    static Json
    array();

    /// Sets (or replaces) a member of an object.
    Json &
    set(const std::string &key, const Json &value);
    /// Appends to an array.
    Json &
    push(const Json &value);

    /// Member @p key of an object (a null value if absent).
    const Json &
    operator[](const std::string &key) const;
    /// Element @p i of an array (a null value if absent).
    const Json &
    operator[](const std::size_t i) const;
    /// The number of elements of an array (0 for any other value).
    std::size_t
    size() const
    {
      return type == Type::array ? items.size() : 0;
    }
    /// The number held (NaN if the value is not a number).
    double
    number_value() const;

    /// Writes the value; non-finite numbers become null.
    void
    write(std::ostream &out, const unsigned int indent = 0) const;

  private:
    enum class Type
    {
      null,
      boolean,
      number,
      string,
      array,
      object
    } type;
    double                                    number  = 0.;
    bool                                      boolean = false;
    std::string                               text;
    std::vector<Json>                         items;
    std::vector<std::pair<std::string, Json>> members;
  };

  /// The array of the first @p n components of @p v (a vector or tensor).
  template <typename Vector>
  Json
  json_array(const Vector &v, const unsigned int n)
  {
    Json result = Json::array();
    for (unsigned int i = 0; i < n; ++i)
      result.push(v[i]);
    return result;
  }
} // namespace contact_fem

#endif
