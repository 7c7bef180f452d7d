using System.Collections.Generic;
using MagnusBall.Integration;

namespace MagnusBall.Cli
{
    /// <summary>One flight to simulate, as read from a scenario file (all values checked and in SI units).</summary>
    internal sealed record Scenario(
        int Index,
        string Name,
        FlightModel Model,
        FlightState Initial,
        IIntegrator Integrator,
        double Step,
        NamedPlane? Ground,
        IReadOnlyList<NamedPlane> Planes,
        double MaxTime,
        IReadOnlyList<string>? Warnings = null,
        IReadOnlyList<MagnusBall.Contact.Shapes.ContactShape>? Shapes = null);

    /// <summary>The flight parts a scenario and an aim share: the model, how to step it, the ground, the time limit.</summary>
    internal sealed record FlightSetup(FlightModel Model, IIntegrator Integrator, double Step, NamedPlane? Ground, double MaxTime, MagnusBall.Presets.SportPreset? Preset = null);

    /// <summary>
    /// A named plane through <paramref name="Point"/> with unit normal <paramref name="Normal"/>, and an
    /// optional rectangle on it (<paramref name="Bounds"/>) such as a net or a goal mouth.
    /// </summary>
    internal sealed record NamedPlane(string Name, Vector3d Point, Vector3d Normal, PlaneBounds? Bounds);

    /// <summary>
    /// A rectangle on a plane, in the plane's own axes through its point: "height" runs along the frame's up
    /// direction projected onto the plane, "width" along normal x that height axis. A missing limit is
    /// unbounded. A crossing reports whether it passed inside the rectangle.
    /// </summary>
    internal sealed record PlaneBounds(Vector3d HeightAxis, Vector3d WidthAxis, double HeightMin, double HeightMax, double WidthMin, double WidthMax)
    {
        /// <summary>
        /// (height, width) of <paramref name="position"/> in the plane's axes, relative to <paramref name="origin"/>. For
        /// finite input never NaN: a coordinate is infinite only where it exceeds what a double holds (points near 1e308
        /// apart), as <see cref="Plane.SignedDistance"/> forms a distance.
        /// </summary>
        public (double Height, double Width) Coordinates(Vector3d position, Vector3d origin) =>
            (Along(position, origin, HeightAxis), Along(position, origin, WidthAxis));

        /// <summary>
        /// Whether the point lies within the rectangle (limits included). A coordinate beyond what a double holds is
        /// infinite, so it is outside a finite limit and inside a missing (unbounded) one.
        /// </summary>
        public bool Contains(Vector3d position, Vector3d origin)
        {
            (double height, double width) = Coordinates(position, origin);
            return height >= HeightMin && height <= HeightMax && width >= WidthMin && width <= WidthMax;
        }

        // The plain (position - origin) . axis, and where it is not finite (a component of the difference overflowed: inf * 0
        // beside a zero axis component, or inf - inf between products), 4 times the same formed from quarters, which cannot
        // overflow for finite input (each quarter-difference is at most double.MaxValue / 2 and the axis is a unit vector;
        // the reasoning of Plane.SignedDistance). The common case is the plain formula, unchanged to the bit.
        private static double Along(Vector3d position, Vector3d origin, Vector3d axis)
        {
            double d = Vector3d.Dot(position - origin, axis);
            return double.IsFinite(d) ? d : 4 * FromQuarters(position, origin, axis);
        }

        private static double FromQuarters(Vector3d p, Vector3d o, Vector3d a) =>
            (0.25 * p.X - 0.25 * o.X) * a.X + (0.25 * p.Y - 0.25 * o.Y) * a.Y + (0.25 * p.Z - 0.25 * o.Z) * a.Z;
    }
}
