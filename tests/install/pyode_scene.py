#!/usr/bin/env python3
"""pyode_scene.py -- the scene of scene_program.c (a sphere thrown onto a
plane, a hinge pendulum) scripted through PyODE, Debian's python3-pyode,
which is compiled against libode.so.8. check_install.sh runs it on the
reference ODE and on ours (LD_LIBRARY_PATH) and compares the lines, each
    name tolerance value value ..."""
import ode

RADIUS = 0.5


def main():
    world = ode.World()
    world.setGravity((0, 0, -9.81))
    world.setERP(0.2)
    world.setCFM(1e-5)
    space = ode.SimpleSpace()
    contacts = ode.JointGroup()
    plane = ode.GeomPlane(space, (0, 0, 1), 0)   # a PyODE geom lives as long as its object

    ball = ode.Body(world)
    m = ode.Mass()
    m.setSphereTotal(1, RADIUS)
    ball.setMass(m)
    ball.setPosition((0, 0, 1.5))
    ball.setLinearVel((2, 0, 0))
    sphere = ode.GeomSphere(space, RADIUS)
    sphere.setBody(ball)

    bob = ode.Body(world)
    m = ode.Mass()
    m.setBoxTotal(1, 0.1, 0.1, 0.1)
    bob.setMass(m)
    bob.setPosition((1, 5, 3))
    hinge = ode.HingeJoint(world)
    hinge.attach(bob, ode.environment)
    hinge.setAnchor((0, 5, 3))
    hinge.setAxis((0, 1, 0))

    def near(_, a, b):
        for c in ode.collide(a, b):
            c.setMode(ode.ContactApprox1)
            c.setMu(0.4)
            j = ode.ContactJoint(world, contacts, c)
            j.attach(a.getBody(), b.getBody())

    for step in range(1, 301):
        space.collide(None, near)
        world.step(0.01)
        contacts.empty()
        if step % 50 == 0:
            q, v, w = ball.getPosition(), ball.getLinearVel(), ball.getAngularVel()
            p = bob.getPosition()
            print("sphere_%d 2e-3 %.6f %.6f %.6f %.6f %.6f" % (step, q[0], q[2], v[0], v[2], w[1]))
            print("pendulum_%d 2e-3 %.6f %.6f %.6f %.6f"
                  % (step, hinge.getAngle(), hinge.getAngleRate(), p[0], p[2]))


main()
