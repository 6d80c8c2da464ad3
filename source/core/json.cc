#include <contact_fem/core/json.h>

#include <cmath>
#include <cstdio>

namespace contact_fem
{
  Json::Json()
    : type(Type::null)
  {}
  Json::Json(double value)
    : type(Type::number)
    , number(value)
  {}
  Json::Json(int value)
    : type(Type::number)
    , number(value)
  {}
  Json::Json(unsigned int value)
    : type(Type::number)
    , number(value)
  {}
  Json::Json(bool value)
    : type(Type::boolean)
    , boolean(value)
  {}
  Json::Json(const std::string &value)
    : type(Type::string)
    , text(value)
  {}
  Json::Json(const char *value)
    : type(Type::string)
    , text(value)
  {}

  Json
  Json::object()
  {
    Json j;
    j.type = Type::object;
    return j;
  }

  Json
  Json::array()
  {
    Json j;
    j.type = Type::array;
    return j;
  }

  Json &
  Json::set(const std::string &key, const Json &value)
  {
    for (auto &member : members)
      if (member.first == key)
        {
          member.second = value;
          return *this;
        }
    members.emplace_back(key, value);
    return *this;
  }

  Json &
  Json::push(const Json &value)
  {
    items.push_back(value);
    return *this;
  }

  const Json &
  Json::operator[](const std::string &key) const
  {
    static const Json null_value;
    for (const auto &member : members)
      if (member.first == key)
        return member.second;
    return null_value;
  }

  const Json &
  Json::operator[](const std::size_t i) const
  {
    static const Json null_value;
    return type == Type::array && i < items.size() ? items[i] : null_value;
  }

  double
  Json::number_value() const
  {
    return type == Type::number ? number : std::nan("");
  }

  namespace
  {
    void
    write_string(std::ostream &out, const std::string &s)
    {
      out << '"';
      for (const char c : s)
        switch (c)
          {
            case '"':
              out << "\\\"";
              break;
            case '\\':
              out << "\\\\";
              break;
            case '\n':
              out << "\\n";
              break;
            default:
              out << c;
          }
      out << '"';
    }
  } // namespace

  void
  Json::write(std::ostream &out, const unsigned int indent) const
  {
    const std::string pad(indent + 2, ' '), end_pad(indent, ' ');
    switch (type)
      {
        case Type::null:
          out << "null";
          break;
        case Type::boolean:
          out << (boolean ? "true" : "false");
          break;
        case Type::number:
          if (!std::isfinite(number))
            out << "null";
          else
            {
              char buffer[32];
              std::snprintf(buffer, sizeof(buffer), "%.10g", number);
              out << buffer;
            }
          break;
        case Type::string:
          write_string(out, text);
          break;
        case Type::array:
          out << "[";
          for (unsigned int i = 0; i < items.size(); ++i)
            {
              out << (i == 0 ? "\n" : ",\n") << pad;
              items[i].write(out, indent + 2);
            }
          out << (items.empty() ? "]" : "\n" + end_pad + "]");
          break;
        case Type::object:
          out << "{";
          for (unsigned int i = 0; i < members.size(); ++i)
            {
              out << (i == 0 ? "\n" : ",\n") << pad;
              write_string(out, members[i].first);
              out << ": ";
              members[i].second.write(out, indent + 2);
            }
          out << (members.empty() ? "}" : "\n" + end_pad + "}");
          break;
      }
  }
} // namespace contact_fem
