// ColliderShapes: MagnusBall contact shapes built from a scene's colliders where the match is exact (issue 40). MagnusBallFlight
// builds its shapeColliders with it.
#nullable enable
using System;
using System.Collections.Generic;
using MagnusBall.Contact;
using MagnusBall.Contact.Shapes;
using UnityEngine;

namespace MagnusBall.Components
{
    /// <summary>
    /// Builds MagnusBall contact shapes (MagnusBall.Contact.Shapes) from Unity colliders where the match is exact: a
    /// <c>BoxCollider</c> becomes a <see cref="BoxShape"/> (its centre and its three half-size axes through the transform, which
    /// must keep them square: no skew from a non-uniform parent scale under rotation), a <c>CapsuleCollider</c> a
    /// <see cref="CapsuleShape"/> (its axis through the transform, whose scale must be the same in the two directions across the
    /// axis), a <c>SphereCollider</c> (and a capsule no longer than its diameter, which Unity makes a sphere) a
    /// <see cref="SphereShape"/> (its transform must scale it the same along all three axes). Anything else is skipped with a
    /// warning (Debug.LogWarning) naming it and why: a mesh collider, a skewed box, a sphere scaled unevenly.
    /// </summary>
    public static class ColliderShapes
    {
        /// <summary>Relative tolerance of the exactness checks (the transform's floats carry about 1e-7).</summary>
        private const double Tolerance = 1e-5;

        /// <summary>
        /// The shapes of <paramref name="colliders"/> that match exactly, in order; the collider at index i gets id
        /// <paramref name="firstId"/> + i (a skipped one leaves its id unused, so ids stay put when a collider is fixed).
        /// </summary>
        /// <param name="colliders">The colliders; null elements are skipped with a warning.</param>
        /// <param name="contact">The contact parameters of every shape (restitution, friction).</param>
        /// <param name="firstId">The id of the first collider's shape.</param>
        /// <param name="skipped">Where to add one line per skipped collider (also logged as a warning); may be null.</param>
        /// <returns>The shapes, a new array.</returns>
        /// <exception cref="ArgumentNullException"><paramref name="colliders"/> is null.</exception>
        public static ContactShape[] FromColliders(IReadOnlyList<Collider?> colliders, ContactProperties contact, int firstId = 0, List<string>? skipped = null)
        {
            if (colliders == null)
            {
                throw new ArgumentNullException(nameof(colliders));
            }

            var shapes = new List<ContactShape>(colliders.Count);
            for (int i = 0; i < colliders.Count; i++)
            {
                Collider? collider = colliders[i];
                string? why = $"shapeColliders[{i}] is empty (no collider assigned)";
                ContactShape? shape = collider == null ? null : TryBuild(collider, contact, firstId + i, out why);

                if (shape != null)
                {
                    shapes.Add(shape);
                    continue;
                }

                string message = $"MagnusBall: collider {i} ('{(collider == null ? "none" : collider.name)}') skipped: {why}.";
                skipped?.Add(message);
                Debug.LogWarning(message, collider);
            }

            return shapes.ToArray();
        }

        /// <summary>The shape of one collider where the match is exact, else null with the reason.</summary>
        internal static ContactShape? TryBuild(Collider collider, ContactProperties contact, int id, out string? why)
        {
            why = null;
            Transform t = collider.transform;
            switch (collider)
            {
                case BoxCollider box:
                {
                    Vector3 half = new Vector3(box.size.x * 0.5f, box.size.y * 0.5f, box.size.z * 0.5f);
                    Vector3d centre = HalfAxes(t, box.center, half, out Vector3d x, out Vector3d y, out Vector3d z);
                    if (!(half.x > 0 && half.y > 0 && half.z > 0))
                    {
                        why = "a BoxCollider's size must be > 0 along every axis";
                        return null;
                    }

                    if (!Square(x, y) || !Square(y, z) || !Square(x, z))
                    {
                        why = "its transform skews the box (a non-uniform parent scale under rotation); MagnusBall's BoxShape is a right box";
                        return null;
                    }

                    return new BoxShape(id, centre, new Vector3d(x.Length, y.Length, z.Length), x, y, contact);
                }

                case CapsuleCollider capsule:
                {
                    if (capsule.direction < 0 || capsule.direction > 2)
                    {
                        why = $"a CapsuleCollider's direction must be 0, 1 or 2 (x, y, z); got {capsule.direction}";
                        return null;
                    }

                    Vector3 c = capsule.center;
                    int axis = capsule.direction;
                    Vector3d centre = World(t, c);
                    Vector3d r1 = World(t, Offset(c, (axis + 1) % 3, capsule.radius)) - centre, r2 = World(t, Offset(c, (axis + 2) % 3, capsule.radius)) - centre;
                    Vector3d along = World(t, Offset(c, axis, 1)) - centre;
                    double radius = r1.Length;
                    if (!(capsule.radius > 0) || !(radius > 0))
                    {
                        why = "a CapsuleCollider's radius must be > 0";
                        return null;
                    }

                    if (Math.Abs(r2.Length - radius) > Tolerance * radius || !Square(r1, r2) || !Square(r1, along) || !Square(r2, along))
                    {
                        why = "its transform scales the capsule differently across its axis (it would be elliptical); MagnusBall's CapsuleShape is round";
                        return null;
                    }

                    // Unity's capsule: height is end to end, round caps included; up to twice the radius it is a sphere.
                    double halfLine = 0.5 * capsule.height - capsule.radius;
                    if (!(halfLine > 0))
                    {
                        return Sphere(t, c, capsule.radius, contact, id, out why);
                    }

                    Vector3d a = World(t, Offset(c, axis, -(float)halfLine)), b = World(t, Offset(c, axis, (float)halfLine));
                    // Unity keeps the caps round at the largest scale across the axis; the checks above make both the same.
                    return new CapsuleShape(id, a, b, radius, contact);
                }

                case SphereCollider sphere:
                    return Sphere(t, sphere.center, sphere.radius, contact, id, out why);
                default:
                    why = $"a {collider.GetType().Name} has no exact MagnusBall shape (boxes, capsules and spheres do)";
                    return null;
            }
        }

        // A sphere of local radius `radius` at local point c: exact where the transform scales all three axes alike (Unity scales
        // an unevenly scaled sphere collider by one of its scales; that choice is not matched here).
        private static ContactShape? Sphere(Transform t, Vector3 c, float radius, ContactProperties contact, int id, out string? why)
        {
            why = null;
            if (!(radius > 0))
            {
                why = "a sphere's radius must be > 0";
                return null;
            }

            Vector3d centre = HalfAxes(t, c, new Vector3(radius, radius, radius), out Vector3d x, out Vector3d y, out Vector3d z);
            double r = x.Length;
            if (!(r > 0) || Math.Abs(y.Length - r) > Tolerance * r || Math.Abs(z.Length - r) > Tolerance * r || !Square(x, y) || !Square(y, z) || !Square(x, z))
            {
                why = "its transform scales the sphere differently along its axes (it would be an ellipsoid); MagnusBall's SphereShape is round";
                return null;
            }

            return new SphereShape(id, centre, r, contact);
        }

        // The world centre of local point c and the world vectors from it to c moved by half.x, half.y and half.z along the local
        // x, y and z axes (through the transform, its rotation and scale).
        private static Vector3d HalfAxes(Transform t, Vector3 c, Vector3 half, out Vector3d x, out Vector3d y, out Vector3d z)
        {
            Vector3d centre = World(t, c);
            x = World(t, Offset(c, 0, half.x)) - centre;
            y = World(t, Offset(c, 1, half.y)) - centre;
            z = World(t, Offset(c, 2, half.z)) - centre;
            return centre;
        }

        private static Vector3d World(Transform t, Vector3 local) => UnityFrame.ToLibrary(t.TransformPoint(local));

        // The local point c moved by `length` along local axis 0, 1 or 2 (x, y, z).
        private static Vector3 Offset(Vector3 c, int axis, float length) =>
            axis == 0 ? new Vector3(c.x + length, c.y, c.z) : axis == 1 ? new Vector3(c.x, c.y + length, c.z) : new Vector3(c.x, c.y, c.z + length);

        // Two directions at a right angle, within the tolerance.
        private static bool Square(in Vector3d a, in Vector3d b) => Math.Abs(Vector3d.Dot(a, b)) <= Tolerance * a.Length * b.Length;
    }
}
