// headers_cpp.cpp -- built as C++11 with -pedantic -Werror: the public headers
// must compile cleanly for C++ programs. Building is the test.
#include <ode/ode.h>

int main()
{
    dMass m;   // the C++ constructor zeroes it
    m.setBox(1, 1, 2, 3);
    return m.mass == 6 ? 0 : 1;
}
