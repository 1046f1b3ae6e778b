// babylon-node.js - Babylon.js's Vector3.getNormalToRef, completed as the
// study completes it (normalize(), then Vector3.CrossToRef(n, b1)), run by
// Node.js itself: the golden bits of the `babylon` row
// (tests/data/babylon_node.csv, written by scripts/babylon-node.sh).
// The methods below are Babylon.js's lines (github.com/BabylonJS/Babylon.js
// 141e38dddee1ac94408a53bacf22508973697532,
// packages/dev/core/src/Maths/math.vector.ts, Apache-2.0) with their
// TypeScript types and _isDirty bookkeeping removed; the class is a minimal
// stand-in for Babylon's Vector3.
"use strict";
class Vector3 {
    constructor(x = 0, y = 0, z = 0) { this._x = x; this._y = y; this._z = z; }
    get x() { return this._x; }
    get y() { return this._y; }
    get z() { return this._z; }
    set(x, y, z) { this._x = x; this._y = y; this._z = z; return this; }
    scaleInPlace(scale) {
        this._x *= scale;
        this._y *= scale;
        this._z *= scale;
        return this;
    }
    length() {
        return Math.sqrt(this.lengthSquared());
    }
    lengthSquared() {
        return this._x * this._x + this._y * this._y + this._z * this._z;
    }
    normalize() {
        return this.normalizeFromLength(this.length());
    }
    normalizeFromLength(len) {
        if (len === 0 || len === 1.0) {
            return this;
        }
        return this.scaleInPlace(1.0 / len);
    }
    getNormalToRef(result) {
        const radius = this.length();
        let theta = Math.acos(this.y / radius);
        const phi = Math.atan2(this.z, this.x);
        //makes angle 90 degs to current vector
        if (theta > Math.PI / 2) {
            theta -= Math.PI / 2;
        } else {
            theta += Math.PI / 2;
        }
        //Calculates resutant normal vector from spherical coordinate of perpendicular vector
        const x = radius * Math.sin(theta) * Math.cos(phi);
        const y = radius * Math.cos(theta);
        const z = radius * Math.sin(theta) * Math.sin(phi);
        result.set(x, y, z);
        return result;
    }
    static CrossToRef(left, right, result) {
        const x = left._y * right._z - left._z * right._y;
        const y = left._z * right._x - left._x * right._z;
        const z = left._x * right._y - left._y * right._x;
        result.set(x, y, z);
        return result;
    }
}

const f64 = new Float64Array(1), u64 = new BigUint64Array(f64.buffer);
const hex = (v) => { f64[0] = v; return u64[0].toString(16).padStart(16, "0"); };
// a 64-bit LCG (Knuth's MMIX constants), seeded by argv[3]
let s = BigInt(process.argv[3] || 1);
const rnd = () => { s = (s * 6364136223846793005n + 1442695040888963407n) & ((1n << 64n) - 1n); return Number(s >> 11n) / 2 ** 53; };
const N = +(process.argv[2] || 1000);
const inputs = [
    [1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1],
    [-0, 1, 0], [-0, -1, 0], [0, 1, -0], [-0, 1, -0], [-0, -1, -0],
    [1e-300, 1, 0], [0, 1, 1e-300], [-1e-9, 1, 1e-9], [1e-8, 1, -1e-8], [2 ** -27, 1, 0],
    [1, 0, 1e-25], [1, 1e-17, 0], [1, -1e-17, 0], [0.6, 0, 0.8], [0.6, -0, 0.8],
    [Math.SQRT1_2, Math.SQRT1_2, 0], [0, Math.SQRT1_2, -Math.SQRT1_2],
    [2, 0, 0], [0, 3, 4], [0, 0, 0], [NaN, 0, 1], [Infinity, 0, 0], [5e-324, 0, 0],
];
for (let i = 0; inputs.length < N; i++) {
    let x = rnd() * 2 - 1, y = rnd() * 2 - 1, z = rnd() * 2 - 1;
    if (i % 4 === 1) { x *= 1e-7; z *= 1e-7; y = y < 0 ? -1 : 1; }          // near +-y
    if (i % 4 === 2) { y *= 1e-9; }                                            // near y = 0
    const l = Math.sqrt(x * x + y * y + z * z);
    if (l === 0) continue;
    inputs.push([x / l, y / l, z / l]);
}
const out = ["nx,ny,nz,b1x,b1y,b1z,b2x,b2y,b2z"];
for (const [x, y, z] of inputs) {
    const n = new Vector3(x, y, z), b1 = new Vector3(), b2 = new Vector3();
    n.getNormalToRef(b1);
    b1.normalize();
    Vector3.CrossToRef(n, b1, b2);
    out.push([x, y, z, b1.x, b1.y, b1.z, b2.x, b2.y, b2.z].map(hex).join(","));
}
console.log(out.join("\n"));
