// colcon-rsia model of <xmlrpcpp/XmlRpcValue.h>: XmlRpc::XmlRpcValue, the
// structured parameter type of NodeHandle::getParam.
#ifndef RSIA_MODEL_XMLRPCPP_XMLRPCVALUE_H
#define RSIA_MODEL_XMLRPCPP_XMLRPCVALUE_H

#include <map>
#include <string>
#include <vector>

namespace XmlRpc
{

class XmlRpcValue
{
public:
  enum Type
  {
    TypeInvalid,
    TypeBoolean,
    TypeInt,
    TypeDouble,
    TypeString,
    TypeDateTime,
    TypeBase64,
    TypeArray,
    TypeStruct,
  };
  typedef std::vector<char> BinaryData;
  typedef std::vector<XmlRpcValue> ValueArray;
  typedef std::map<std::string, XmlRpcValue> ValueStruct;
  typedef ValueStruct::iterator iterator;
  typedef ValueStruct::const_iterator const_iterator;

  XmlRpcValue();
  XmlRpcValue(bool value);
  XmlRpcValue(int value);
  XmlRpcValue(double value);
  XmlRpcValue(std::string const& value);
  XmlRpcValue(const char* value);
  XmlRpcValue(XmlRpcValue const& rhs);
  ~XmlRpcValue();

  void clear();
  XmlRpcValue& operator=(XmlRpcValue const& rhs);
  XmlRpcValue& operator=(int const& rhs);
  XmlRpcValue& operator=(double const& rhs);
  XmlRpcValue& operator=(const char* rhs);
  bool operator==(XmlRpcValue const& other) const;
  bool operator!=(XmlRpcValue const& other) const;

  operator bool&();
  operator int&();
  operator double&();
  operator std::string&();
  operator BinaryData&();
  operator struct tm&();

  XmlRpcValue const& operator[](int i) const;
  XmlRpcValue& operator[](int i);
  XmlRpcValue& operator[](std::string const& k);
  XmlRpcValue& operator[](const char* k);

  iterator begin();
  iterator end();
  const_iterator begin() const;
  const_iterator end() const;

  bool valid() const;
  Type const& getType() const;
  int size() const;
  void setSize(int size);
  bool hasMember(const std::string& name) const;
  std::string toXml() const;
};

}  // namespace XmlRpc

#endif  // RSIA_MODEL_XMLRPCPP_XMLRPCVALUE_H
