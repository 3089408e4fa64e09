// ode_program.c -- an ordinary ODE program (support functions only, for now),
// built by check_install.sh against the installed library the ways users
// build ODE programs: `pkg-config ode`, and plain -lode.
#include <ode/ode.h>

int main(void)
{
    dInitODE();
    dMass m;
    dMassSetBoxTotal(&m, 2, 1, 2, 3);
    dMatrix3 R;
    dQuaternion q;
    dRFromAxisAndAngle(R, 0, 0, 1, M_PI / 2);
    dRtoQ(R, q);   // the 0.5 name
    int ok = dMassCheck(&m) && fabs(m.I[0] - 2.0 * (4 + 9) / 12) < 1e-6 && fabs(R[4] - 1) < 1e-6;
    dCloseODE();
    printf("%s\n", ok ? "ok" : "wrong");
    return ok ? 0 : 1;
}
