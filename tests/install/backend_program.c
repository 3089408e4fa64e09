// backend_program.c NAME -- built by check_install.sh against the installed
// library: the backend module NAME is listed, loads when selected (it was not
// mapped before), and finds a box 0.01 deep in a plane.
#include <ode/ode.h>
#include <ode/backend.h>
#include <stdio.h>
#include <string.h>

static int mapped(const char *text)
{
    FILE *f = fopen("/proc/self/maps", "r");
    char line[4096];
    int found = 0;
    while (f && !found && fgets(line, sizeof line, f)) found = strstr(line, text) != NULL;
    if (f) fclose(f);
    return found;
}

int main(int argc, char **argv)
{
    if (argc != 2) return 2;
    char file[128];
    snprintf(file, sizeof file, "libodecollide-%s.so", argv[1]);
    dInitODE();
    int listed = 0;
    for (const char *const *n = dCollisionListBackends(); *n; n++)
        listed |= strcmp(*n, argv[1]) == 0;
    if (!listed || mapped(file)) {
        printf("%s: %s\n", argv[1], listed ? "mapped before selection" : "not listed");
        return 1;
    }
    if (!dCollisionSetBackend(argv[1]) || !mapped(file)) return 1;
    dGeomID plane = dCreatePlane(0, 0, 0, 1, 0), box = dCreateBox(0, 1, 1, 1);
    dGeomSetPosition(box, 0, 0, 0.49);
    dContactGeom c[8];
    int n = dCollide(box, plane, 8, c, sizeof c[0]);
    int ok = n >= 1 && fabs(c[0].depth - 0.01) < 1e-4 &&
             strcmp(dCollisionGetBackend(), argv[1]) == 0;
    dGeomDestroy(plane);
    dGeomDestroy(box);
    dCloseODE();
    printf("%s: %d contacts, %s\n", argv[1], n, ok ? "ok" : "wrong");
    return ok ? 0 : 1;
}
