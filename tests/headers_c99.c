// headers_c99.c -- built with -std=c99 -pedantic -Werror: the public headers
// must compile cleanly for strict C99 programs. Building is the test.
#include <ode/ode.h>

int main(void)
{
    dMatrix3 R;
    dRSetIdentity(R);
    return R[0] == 1 ? 0 : 1;
}
