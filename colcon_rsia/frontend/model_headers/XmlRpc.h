// colcon-rsia model of <XmlRpc.h> (found through -I/usr/include/xmlrpcpp).
#include <xmlrpcpp/XmlRpcValue.h>
