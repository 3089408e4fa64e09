// SPDX-License-Identifier: BSD-3-Clause
//
// odecpp_collision.h -- the C++ wrappers of ODE 0.16 for geoms and spaces.
// Header-only: every method is an inline call of the C function it names.
//
// As in ODE: dGeom owns a dGeomID and destroys it in its (non-virtual) destructor;
// dSpace is a dGeom that also converts to dSpaceID; each space and geom class adds
// its constructors (optionally inside a parent space) and its own accessors. None
// can be copied (copy constructor and assignment are private and never defined).
// A geom class constructed without arguments holds no geom until create().
// A space destroyed with cleanup on destroys its geoms: their wrappers must not
// outlive it (declare the space first, so it is destroyed last).
#ifndef ODE_ODECPP_COLLISION_H
#define ODE_ODECPP_COLLISION_H
#ifdef __cplusplus

#include <ode/common.h>
#include <ode/collision.h>

class dGeom {
    dGeom(dGeom &);   // not copyable
    void operator=(dGeom &);

protected:
    dGeomID _id;

    dGeom() { _id = 0; }

public:
    ~dGeom()
    {
        if (_id) dGeomDestroy(_id);
    }

    dGeomID id() const { return _id; }
    operator dGeomID() const { return _id; }

    // Destroys the geom held, if any; the wrapper then holds none.
    void destroy()
    {
        if (_id) dGeomDestroy(_id);
        _id = 0;
    }

    int getClass() const { return dGeomGetClass(_id); }
    dSpaceID getSpace() const { return dGeomGetSpace(_id); }

    void setData(void *data) { dGeomSetData(_id, data); }
    void *getData() const { return dGeomGetData(_id); }

    void setBody(dBodyID b) { dGeomSetBody(_id, b); }
    dBodyID getBody() const { return dGeomGetBody(_id); }

    void setPosition(dReal x, dReal y, dReal z) { dGeomSetPosition(_id, x, y, z); }
    const dReal *getPosition() const { return dGeomGetPosition(_id); }
    void setRotation(const dMatrix3 R) { dGeomSetRotation(_id, R); }
    const dReal *getRotation() const { return dGeomGetRotation(_id); }
    void setQuaternion(const dQuaternion quat) { dGeomSetQuaternion(_id, quat); }
    void getQuaternion(dQuaternion quat) const { dGeomGetQuaternion(_id, quat); }

    // aabb = (minx, maxx, miny, maxy, minz, maxz).
    void getAABB(dReal aabb[6]) const { dGeomGetAABB(_id, aabb); }

    // The getters below are not const in ODE 0.16; they stay so for compatibility.
    int isSpace() { return dGeomIsSpace(_id); }

    void setCategoryBits(unsigned long bits) { dGeomSetCategoryBits(_id, bits); }
    void setCollideBits(unsigned long bits) { dGeomSetCollideBits(_id, bits); }
    unsigned long getCategoryBits() { return dGeomGetCategoryBits(_id); }
    unsigned long getCollideBits() { return dGeomGetCollideBits(_id); }

    void enable() { dGeomEnable(_id); }
    void disable() { dGeomDisable(_id); }
    int isEnabled() { return dGeomIsEnabled(_id); }

    void getRelPointPos(dReal px, dReal py, dReal pz, dVector3 result) const
    {
        dGeomGetRelPointPos(_id, px, py, pz, result);
    }
    void getRelPointPos(const dVector3 p, dVector3 result) const
    {
        getRelPointPos(p[0], p[1], p[2], result);
    }
    void getPosRelPoint(dReal px, dReal py, dReal pz, dVector3 result) const
    {
        dGeomGetPosRelPoint(_id, px, py, pz, result);
    }
    void getPosRelPoint(const dVector3 p, dVector3 result) const
    {
        getPosRelPoint(p[0], p[1], p[2], result);
    }
    void vectorToWorld(dReal px, dReal py, dReal pz, dVector3 result) const
    {
        dGeomVectorToWorld(_id, px, py, pz, result);
    }
    void vectorToWorld(const dVector3 p, dVector3 result) const
    {
        vectorToWorld(p[0], p[1], p[2], result);
    }
    void vectorFromWorld(dReal px, dReal py, dReal pz, dVector3 result) const
    {
        dGeomVectorFromWorld(_id, px, py, pz, result);
    }
    void vectorFromWorld(const dVector3 p, dVector3 result) const
    {
        vectorFromWorld(p[0], p[1], p[2], result);
    }

    // dSpaceCollide2 of this geom (or space) against g.
    void collide2(dGeomID g, void *data, dNearCallback *callback)
    {
        dSpaceCollide2(_id, g, data, callback);
    }
};

// A space. Not constructible itself: use dSimpleSpace, dHashSpace or dQuadTreeSpace.
class dSpace : public dGeom {
    dSpace(dSpace &);   // not copyable
    void operator=(dSpace &);

protected:
    dSpace() { _id = 0; }

public:
    dSpaceID id() const { return (dSpaceID)_id; }
    operator dSpaceID() const { return (dSpaceID)_id; }

    void setCleanup(int mode) { dSpaceSetCleanup(id(), mode); }
    int getCleanup() { return dSpaceGetCleanup(id()); }

    void add(dGeomID x) { dSpaceAdd(id(), x); }
    void remove(dGeomID x) { dSpaceRemove(id(), x); }
    int query(dGeomID x) { return dSpaceQuery(id(), x); }

    int getNumGeoms() { return dSpaceGetNumGeoms(id()); }
    dGeomID getGeom(int i) { return dSpaceGetGeom(id(), i); }

    void collide(void *data, dNearCallback *callback) { dSpaceCollide(id(), data, callback); }
};

class dSimpleSpace : public dSpace {
    dSimpleSpace(dSimpleSpace &);   // not copyable
    void operator=(dSimpleSpace &);

public:
    dSimpleSpace() { _id = (dGeomID)dSimpleSpaceCreate(0); }
    dSimpleSpace(dSpace &space) { _id = (dGeomID)dSimpleSpaceCreate(space.id()); }
    dSimpleSpace(dSpaceID space) { _id = (dGeomID)dSimpleSpaceCreate(space); }
};

class dHashSpace : public dSpace {
    dHashSpace(dHashSpace &);   // not copyable
    void operator=(dHashSpace &);

public:
    dHashSpace() { _id = (dGeomID)dHashSpaceCreate(0); }
    dHashSpace(dSpace &space) { _id = (dGeomID)dHashSpaceCreate(space.id()); }
    dHashSpace(dSpaceID space) { _id = (dGeomID)dHashSpaceCreate(space); }

    // Cell sizes from 2^minlevel to 2^maxlevel.
    void setLevels(int minlevel, int maxlevel) { dHashSpaceSetLevels(id(), minlevel, maxlevel); }
};

class dQuadTreeSpace : public dSpace {
    dQuadTreeSpace(dQuadTreeSpace &);   // not copyable
    void operator=(dQuadTreeSpace &);

public:
    dQuadTreeSpace(const dVector3 center, const dVector3 extents, int depth)
    {
        _id = (dGeomID)dQuadTreeSpaceCreate(0, center, extents, depth);
    }
    dQuadTreeSpace(dSpace &space, const dVector3 center, const dVector3 extents, int depth)
    {
        _id = (dGeomID)dQuadTreeSpaceCreate(space.id(), center, extents, depth);
    }
    dQuadTreeSpace(dSpaceID space, const dVector3 center, const dVector3 extents, int depth)
    {
        _id = (dGeomID)dQuadTreeSpaceCreate(space, center, extents, depth);
    }
};

class dSphere : public dGeom {
    dSphere(dSphere &);   // not copyable
    void operator=(dSphere &);

public:
    dSphere() {}
    dSphere(dReal radius) { _id = dCreateSphere(0, radius); }
    dSphere(dSpace &space, dReal radius) { _id = dCreateSphere(space.id(), radius); }
    dSphere(dSpaceID space, dReal radius) { _id = dCreateSphere(space, radius); }

    // Destroys the geom held, if any, and creates a new one.
    void create(dSpaceID space, dReal radius)
    {
        if (_id) dGeomDestroy(_id);
        _id = dCreateSphere(space, radius);
    }

    void setRadius(dReal radius) { dGeomSphereSetRadius(_id, radius); }
    dReal getRadius() const { return dGeomSphereGetRadius(_id); }
};

class dBox : public dGeom {
    dBox(dBox &);   // not copyable
    void operator=(dBox &);

public:
    dBox() {}
    dBox(dReal lx, dReal ly, dReal lz) { _id = dCreateBox(0, lx, ly, lz); }
    dBox(dSpace &space, dReal lx, dReal ly, dReal lz) { _id = dCreateBox(space.id(), lx, ly, lz); }
    dBox(dSpaceID space, dReal lx, dReal ly, dReal lz) { _id = dCreateBox(space, lx, ly, lz); }

    void create(dSpaceID space, dReal lx, dReal ly, dReal lz)
    {
        if (_id) dGeomDestroy(_id);
        _id = dCreateBox(space, lx, ly, lz);
    }

    void setLengths(dReal lx, dReal ly, dReal lz) { dGeomBoxSetLengths(_id, lx, ly, lz); }
    void getLengths(dVector3 result) const { dGeomBoxGetLengths(_id, result); }
};

// The plane a*x + b*y + c*z = d.
class dPlane : public dGeom {
    dPlane(dPlane &);   // not copyable
    void operator=(dPlane &);

public:
    dPlane() {}
    dPlane(dReal a, dReal b, dReal c, dReal d) { _id = dCreatePlane(0, a, b, c, d); }
    dPlane(dSpace &space, dReal a, dReal b, dReal c, dReal d)
    {
        _id = dCreatePlane(space.id(), a, b, c, d);
    }
    dPlane(dSpaceID space, dReal a, dReal b, dReal c, dReal d)
    {
        _id = dCreatePlane(space, a, b, c, d);
    }

    void create(dSpaceID space, dReal a, dReal b, dReal c, dReal d)
    {
        if (_id) dGeomDestroy(_id);
        _id = dCreatePlane(space, a, b, c, d);
    }

    void setParams(dReal a, dReal b, dReal c, dReal d) { dGeomPlaneSetParams(_id, a, b, c, d); }
    void getParams(dVector4 result) const { dGeomPlaneGetParams(_id, result); }
};

class dCapsule : public dGeom {
    dCapsule(dCapsule &);   // not copyable
    void operator=(dCapsule &);

public:
    dCapsule() {}
    dCapsule(dReal radius, dReal length) { _id = dCreateCapsule(0, radius, length); }
    dCapsule(dSpace &space, dReal radius, dReal length)
    {
        _id = dCreateCapsule(space.id(), radius, length);
    }
    dCapsule(dSpaceID space, dReal radius, dReal length)
    {
        _id = dCreateCapsule(space, radius, length);
    }

    void create(dSpaceID space, dReal radius, dReal length)
    {
        if (_id) dGeomDestroy(_id);
        _id = dCreateCapsule(space, radius, length);
    }

    void setParams(dReal radius, dReal length) { dGeomCapsuleSetParams(_id, radius, length); }
    void getParams(dReal *radius, dReal *length) const
    {
        dGeomCapsuleGetParams(_id, radius, length);
    }
};

class dCylinder : public dGeom {
    dCylinder(dCylinder &);   // not copyable
    void operator=(dCylinder &);

public:
    dCylinder() {}
    dCylinder(dReal radius, dReal length) { _id = dCreateCylinder(0, radius, length); }
    dCylinder(dSpace &space, dReal radius, dReal length)
    {
        _id = dCreateCylinder(space.id(), radius, length);
    }
    dCylinder(dSpaceID space, dReal radius, dReal length)
    {
        _id = dCreateCylinder(space, radius, length);
    }

    void create(dSpaceID space, dReal radius, dReal length)
    {
        if (_id) dGeomDestroy(_id);
        _id = dCreateCylinder(space, radius, length);
    }

    void setParams(dReal radius, dReal length) { dGeomCylinderSetParams(_id, radius, length); }
    void getParams(dReal *radius, dReal *length) const
    {
        dGeomCylinderGetParams(_id, radius, length);
    }
};

// ODE 0.16's dRay also has the deprecated setParams/getParams (dGeomRaySetParams /
// dGeomRayGetParams); those C functions are not declared here yet, so neither are
// the methods. Use setFirstContact / setBackfaceCull instead.
class dRay : public dGeom {
    dRay(dRay &);   // not copyable
    void operator=(dRay &);

public:
    dRay() {}
    dRay(dReal length) { _id = dCreateRay(0, length); }
    dRay(dSpace &space, dReal length) { _id = dCreateRay(space.id(), length); }
    dRay(dSpaceID space, dReal length) { _id = dCreateRay(space, length); }

    void create(dSpaceID space, dReal length)
    {
        if (_id) dGeomDestroy(_id);
        _id = dCreateRay(space, length);
    }

    void setLength(dReal length) { dGeomRaySetLength(_id, length); }
    dReal getLength() { return dGeomRayGetLength(_id); }

    // Start point p and direction d (normalised by the C call).
    void set(dReal px, dReal py, dReal pz, dReal dx, dReal dy, dReal dz)
    {
        dGeomRaySet(_id, px, py, pz, dx, dy, dz);
    }
    void get(dVector3 start, dVector3 dir) { dGeomRayGet(_id, start, dir); }

    void setBackfaceCull(int backfaceCull) { dGeomRaySetBackfaceCull(_id, backfaceCull); }
    int getBackfaceCull() { return dGeomRayGetBackfaceCull(_id); }
    void setFirstContact(int firstContact) { dGeomRaySetFirstContact(_id, firstContact); }
    int getFirstContact() { return dGeomRayGetFirstContact(_id); }
    void setClosestHit(int closestHit) { dGeomRaySetClosestHit(_id, closestHit); }
    int getClosestHit() { return dGeomRayGetClosestHit(_id); }

    // Both flags at once; deprecated with their C functions, as in ODE 0.16
    // (the calls here do not warn: only a program calling these does).
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#endif
    ODE_API_DEPRECATED void setParams(int firstContact, int backfaceCull)
    {
        dGeomRaySetParams(_id, firstContact, backfaceCull);
    }
    ODE_API_DEPRECATED void getParams(int *firstContact, int *backfaceCull)
    {
        dGeomRayGetParams(_id, firstContact, backfaceCull);
    }
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
};

// A geom transform, deprecated in ODE 0.16 (geom offsets replace it) and marked so
// here too: naming the class warns, as with ODE.
class ODE_API_DEPRECATED dGeomTransform : public dGeom {
    dGeomTransform(dGeomTransform &);   // not copyable
    void operator=(dGeomTransform &);

public:
    dGeomTransform() {}
    dGeomTransform(dSpace &space) { _id = dCreateGeomTransform(space.id()); }
    dGeomTransform(dSpaceID space) { _id = dCreateGeomTransform(space); }

    void create(dSpaceID space = 0)
    {
        if (_id) dGeomDestroy(_id);
        _id = dCreateGeomTransform(space);
    }

    void setGeom(dGeomID geom) { dGeomTransformSetGeom(_id, geom); }
    dGeomID getGeom() const { return dGeomTransformGetGeom(_id); }

    void setCleanup(int mode) { dGeomTransformSetCleanup(_id, mode); }
    int getCleanup() { return dGeomTransformGetCleanup(_id); }
    void setInfo(int mode) { dGeomTransformSetInfo(_id, mode); }
    int getInfo() { return dGeomTransformGetInfo(_id); }
};

#endif   // __cplusplus
#endif   // ODE_ODECPP_COLLISION_H
