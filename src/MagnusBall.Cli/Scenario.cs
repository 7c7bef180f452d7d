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
        double MaxTime);

    /// <summary>The flight parts a scenario and an aim share: the model, how to step it, the ground, the time limit.</summary>
    internal sealed record FlightSetup(FlightModel Model, IIntegrator Integrator, double Step, NamedPlane? Ground, double MaxTime);

    /// <summary>
    /// A named plane through <paramref name="Point"/> with unit normal <paramref name="Normal"/>, and an
    /// optional rectangle on it (<paramref name="Bounds"/>) such as a net or a goal mouth.
    /// </summary>
    internal sealed record NamedPlane(string Name, Vector3d Point, Vector3d Normal, PlaneBounds? Bounds)
    {
        /// <summary>Signed distance of <paramref name="position"/> from the plane, positive on the normal's side.</summary>
        public double SignedDistance(Vector3d position) => Vector3d.Dot(position - Point, Normal);
    }

    /// <summary>
    /// A rectangle on a plane, in the plane's own axes through its point: "height" runs along the frame's up
    /// direction projected onto the plane, "width" along normal x that height axis. A missing limit is
    /// unbounded. A crossing reports whether it passed inside the rectangle.
    /// </summary>
    internal sealed record PlaneBounds(Vector3d HeightAxis, Vector3d WidthAxis, double HeightMin, double HeightMax, double WidthMin, double WidthMax)
    {
        /// <summary>(height, width) of <paramref name="position"/> in the plane's axes, relative to <paramref name="origin"/>.</summary>
        public (double Height, double Width) Coordinates(Vector3d position, Vector3d origin) =>
            (Vector3d.Dot(position - origin, HeightAxis), Vector3d.Dot(position - origin, WidthAxis));

        /// <summary>Whether the point lies within the rectangle (limits included).</summary>
        public bool Contains(Vector3d position, Vector3d origin)
        {
            (double height, double width) = Coordinates(position, origin);
            return height >= HeightMin && height <= HeightMax && width >= WidthMin && width <= WidthMax;
        }
    }
}
