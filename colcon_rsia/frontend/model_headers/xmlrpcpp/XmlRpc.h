// colcon-rsia model of <xmlrpcpp/XmlRpc.h>.
#include <xmlrpcpp/XmlRpcValue.h>
