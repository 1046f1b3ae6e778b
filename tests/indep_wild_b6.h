/*
 * indep_wild_b6.h - an independent transliteration of Babylon.js's
 * Vector3.getNormalToRef (github.com/BabylonJS/Babylon.js 141e38dd,
 * packages/dev/core/src/Maths/math.vector.ts), written from the TypeScript
 * as a Vector3 object with its own methods (length via lengthSquared,
 * normalize via normalizeFromLength and scaleInPlace, the static
 * CrossToRef), completed as docs/wild-specs/README.md says: b1 =
 * getNormalToRef(n).normalize(), b2 = CrossToRef(n, b1).  JavaScript's
 * Math.acos, atan2, sin and cos are V8's fdlibm, libonb's onb__fdlibm_*
 * (src/lib/fdlibm.c): they are not written twice here;
 * tests/test_babylon_node.c checks them, and this whole row, against
 * Node.js's own bits.  Babylon.js has no float path: the float row is the
 * double one with b1, b2 rounded to float.
 */
#ifndef INDEP_WILD_B6_H
#define INDEP_WILD_B6_H

typedef struct { double _x, _y, _z; } bjsVector3;

static double bjs_lengthSquared(const bjsVector3 *v) { return v->_x * v->_x + v->_y * v->_y + v->_z * v->_z; }
static double bjs_length(const bjsVector3 *v) { return sqrt(bjs_lengthSquared(v)); }
static bjsVector3 *bjs_scaleInPlace(bjsVector3 *v, double scale)
{
	v->_x *= scale;
	v->_y *= scale;
	v->_z *= scale;
	return v;
}
static bjsVector3 *bjs_normalizeFromLength(bjsVector3 *v, double len)
{
	if (len == 0 || len == 1.0)
		return v;
	return bjs_scaleInPlace(v, 1.0 / len);
}
static bjsVector3 *bjs_normalize(bjsVector3 *v) { return bjs_normalizeFromLength(v, bjs_length(v)); }
static bjsVector3 *bjs_set(bjsVector3 *v, double x, double y, double z)
{
	v->_x = x; v->_y = y; v->_z = z;
	return v;
}
static bjsVector3 *bjs_getNormalToRef(const bjsVector3 *self, bjsVector3 *result)
{
	const double PI = 3.141592653589793;   /* Math.PI */
	const double radius = bjs_length(self);
	double theta = onb__fdlibm_acos(self->_y / radius);
	const double phi = onb__fdlibm_atan2(self->_z, self->_x);
	double x, y, z;
	if (theta > PI / 2)
		theta -= PI / 2;
	else
		theta += PI / 2;
	x = radius * onb__fdlibm_sin(theta) * onb__fdlibm_cos(phi);
	y = radius * onb__fdlibm_cos(theta);
	z = radius * onb__fdlibm_sin(theta) * onb__fdlibm_sin(phi);
	return bjs_set(result, x, y, z);
}
static bjsVector3 *bjs_CrossToRef(const bjsVector3 *left, const bjsVector3 *right, bjsVector3 *result)
{
	const double x = left->_y * right->_z - left->_z * right->_y;
	const double y = left->_z * right->_x - left->_x * right->_z;
	const double z = left->_x * right->_y - left->_y * right->_x;
	return bjs_set(result, x, y, z);
}
static void ind_babylond(Vec3d n, Vec3d *b1, Vec3d *b2)
{
	bjsVector3 v = { n.x, n.y, n.z }, t, c;
	bjs_normalize(bjs_getNormalToRef(&v, &t));
	bjs_CrossToRef(&v, &t, &c);
	*b1 = vd(t._x, t._y, t._z);
	*b2 = vd(c._x, c._y, c._z);
}
static void ind_babylonf(Vec3f n, Vec3f *b1, Vec3f *b2)
{
	Vec3d d1, d2;
	ind_babylond(vd((double)n.x, (double)n.y, (double)n.z), &d1, &d2);
	*b1 = vf((float)d1.x, (float)d1.y, (float)d1.z);
	*b2 = vf((float)d2.x, (float)d2.y, (float)d2.z);
}

/* ids 960 and up (the rows INDEP_WILD_B6_ROWS in tests/indep.h's table) */
enum { IW_BABYLON = 960 };
#define INDEP_WILD_B6_SWITCH(S, V) \
static int indep_wild_b6_##S(int id, V n, V *b1, V *b2) \
{ \
	switch (id) { \
	case IW_BABYLON: ind_babylon##S(n, b1, b2); return 1; \
	default:         return 0; \
	} \
}
INDEP_WILD_B6_SWITCH(f, Vec3f)
INDEP_WILD_B6_SWITCH(d, Vec3d)
/* the table rows, in registry order (after appleseed) */
#define INDEP_WILD_B6_ROWS \
	{ "babylon", onb_babylon, onb_babylonf, IW_BABYLON, 0 },

#endif /* INDEP_WILD_B6_H */
