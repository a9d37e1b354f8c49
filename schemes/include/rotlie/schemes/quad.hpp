#pragma once
// The numeric side's high-precision scalar under one name. Boost's float128 wraps __float128: it
// needs GNU extensions (see the top-level CMakeLists) and libquadmath (linked by rotlie::schemes).
#include <boost/multiprecision/float128.hpp>

namespace rotlie {

using quad = boost::multiprecision::float128;

}  // namespace rotlie
