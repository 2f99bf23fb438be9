// colcon-rsia model of <XmlRpcValue.h> (found through -I/usr/include/xmlrpcpp).
#include <xmlrpcpp/XmlRpcValue.h>
