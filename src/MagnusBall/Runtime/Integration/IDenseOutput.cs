namespace MagnusBall.Integration
{
    /// <summary>
    /// The dense output of one step: the state at any time inside it, and the first time inside it where a
    /// condition changes sign (a plane crossed, the apex). The flight core locates every event through this one
    /// abstraction, so events work the same on a fixed step's cubic Hermite (<see cref="HermiteSegment"/>) and on
    /// an adaptive Dormand-Prince step's own fourth-order interpolant (<see cref="DormandPrince54Step"/>).
    /// Implementations are readonly structs; the core takes them as type parameters, so nothing is boxed.
    /// </summary>
    internal interface IDenseOutput
    {
        /// <summary>The time at the start of the step, s.</summary>
        double StartTime { get; }

        /// <summary>The time at the end of the step, s.</summary>
        double EndTime { get; }

        /// <summary>The interpolated state at <paramref name="time"/> (clamped to the step).</summary>
        /// <param name="time">The time, s.</param>
        FlightState StateAt(double time);

        /// <summary>
        /// The first time inside the step at which the ball's centre crosses <paramref name="plane"/> in
        /// <paramref name="direction"/>, to <see cref="HermiteSegment.TimeTolerance"/>. The step's start counts only
        /// when <paramref name="startsFlight"/> (a ball placed exactly on the plane and heading through it).
        /// </summary>
        /// <param name="plane">The plane.</param>
        /// <param name="direction">Which way the crossing goes.</param>
        /// <param name="startsFlight">True for the first step of a flight.</param>
        /// <param name="time">The crossing time; 0 when none.</param>
        /// <returns>True when the plane is crossed inside the step.</returns>
        bool TryFindCrossing(in Plane plane, CrossingDirection direction, bool startsFlight, out double time);

        /// <summary>The first time inside the step at which the velocity along <paramref name="up"/> falls from positive to zero or below.</summary>
        /// <param name="up">The unit up direction.</param>
        /// <param name="time">The apex time; 0 when none.</param>
        /// <returns>True when the apex is inside the step.</returns>
        bool TryFindApex(in Vector3d up, out double time);
    }
}
