using System;

namespace MagnusBall.Queries
{
    /// <summary>Whether an aim solver found a launch.</summary>
    public enum AimStatus
    {
        /// <summary>A launch was found to the solver's tolerance.</summary>
        Solved = 0,

        /// <summary>No launch within the solver's limits does it; nothing was thrown and nothing diverged.</summary>
        Unreachable = 1,

        /// <summary>
        /// The solve stopped at its work budget (the solver's maximumEvaluationsPerSolve model evaluations plus steps; for
        /// <see cref="SwingAim"/>, its maximumEvaluations) before it could decide; the launch fields hold where it was. Fly
        /// shorter trials (a smaller maximumFlightTime), a larger step or a coarser scan, or give a larger budget.
        /// </summary>
        WorkLimitReached = 2,

        /// <summary>
        /// The target is reached at this speed, but every launch that reaches it hits the obstacle (its bottom passes
        /// below the <see cref="AimObstacle"/>'s top) or touches one of the solver's shapes on the way: the fields describe
        /// the blocked launch (for <see cref="AimSolution.Miss"/>, how far the ball's bottom passes below the obstacle's top,
        /// m, negative; for a shape, the blocked launch's distance from the target as its trial flew without the shape).
        /// </summary>
        Blocked = 3,
    }

    /// <summary>
    /// The result of an aim solve: the status, the launch (speed, elevation, azimuth, and the world-frame
    /// velocity and spin they resolve to), where the solved shot arrives, and what the solve cost.
    /// </summary>
    public readonly struct AimSolution
    {
        /// <summary>Creates a result.</summary>
        /// <param name="status">Solved or unreachable.</param>
        /// <param name="speed">Launch speed, m/s.</param>
        /// <param name="elevationRadians">Launch elevation, rad.</param>
        /// <param name="azimuthFromTargetRadians">Launch azimuth from the direction to the target (the solve's frame's forward) toward its side, rad.</param>
        /// <param name="velocity">Launch velocity, m/s (world frame).</param>
        /// <param name="angularVelocity">Launch angular velocity, rad/s (world frame).</param>
        /// <param name="arrival">The solved shot's state where it crosses the target or obstacle plane.</param>
        /// <param name="miss">See <see cref="Miss"/>.</param>
        /// <param name="simulations">Flights simulated.</param>
        internal AimSolution(
            AimStatus status, double speed, double elevationRadians, double azimuthFromTargetRadians, in Vector3d velocity, in Vector3d angularVelocity,
            in FlightState arrival, double miss, int simulations)
        {
            Status = status;
            Speed = speed;
            ElevationRadians = elevationRadians;
            AzimuthFromTargetRadians = azimuthFromTargetRadians;
            Velocity = velocity;
            AngularVelocity = angularVelocity;
            Arrival = arrival;
            Miss = miss;
            Simulations = simulations;
        }

        /// <summary>Solved, unreachable, blocked by the obstacle or stopped at the work budget. When not solved, the other fields describe the best attempt or are zero.</summary>
        public readonly AimStatus Status;

        /// <summary>Launch speed, m/s.</summary>
        public readonly double Speed;

        /// <summary>Launch elevation above the horizontal, rad.</summary>
        public readonly double ElevationRadians;

        /// <summary>
        /// Launch azimuth about up from the direction to the target, toward the side, rad: the angle of the solve's own frame
        /// (up, forward the horizontal direction from the launch point to the target; for
        /// <see cref="AimSolver.MinimumElevationToClear"/>, the plane's normal), not of the caller's. 0 aims straight at the
        /// target; a curling kick aims off it. For the direction in your own frame use <see cref="AzimuthDegreesIn"/> or
        /// <see cref="Velocity"/>.
        /// </summary>
        public readonly double AzimuthFromTargetRadians;

        /// <summary>The launch velocity in the world frame, m/s: Speed times the launch direction.</summary>
        public readonly Vector3d Velocity;

        /// <summary>The launch angular velocity in the world frame, rad/s (the <see cref="LaunchSpin"/> resolved for this launch).</summary>
        public readonly Vector3d AngularVelocity;

        /// <summary>The solved shot's interpolated state where it crosses the target plane (or the obstacle plane).</summary>
        public readonly FlightState Arrival;

        /// <summary>
        /// For target solves, the distance from <see cref="Arrival"/> to the target, m. For
        /// <see cref="AimSolver.MinimumElevationToClear"/>, how far above the required height the solved shot
        /// crosses the plane, m (0 up to the tolerance).
        /// </summary>
        public readonly double Miss;

        /// <summary>How many flights the solve simulated (its cost: each is a full prediction).</summary>
        public readonly int Simulations;

        /// <summary>True when <see cref="Status"/> is <see cref="AimStatus.Solved"/>.</summary>
        public bool IsSolved => Status == AimStatus.Solved;

        /// <summary>Launch elevation, degrees.</summary>
        public double ElevationDegrees => ElevationRadians * (180 / Math.PI);

        /// <summary>Launch azimuth from the direction to the target toward the side, degrees (see <see cref="AzimuthFromTargetRadians"/>).</summary>
        public double AzimuthFromTargetDegrees => AzimuthFromTargetRadians * (180 / Math.PI);

        /// <summary>
        /// The launch's azimuth in <paramref name="frame"/>: the angle about its up from its forward toward its side of
        /// <see cref="Velocity"/>'s horizontal part, degrees in (-180, 180], the angle <see cref="LaunchFrame.Direction"/>
        /// takes (in radians) to launch this way. A free kick aimed 9.4 degrees left of the target can head 3 degrees right
        /// of the pitch's forward: this gives the 3. 0 for an unsolved result (no velocity) or a frame whose forward is unset.
        /// </summary>
        /// <param name="frame">The frame to measure in (the pitch's, the court's).</param>
        public double AzimuthDegreesIn(in LaunchFrame frame)
        {
            double forward = Vector3d.Dot(Velocity, frame.Forward), side = Vector3d.Dot(Velocity, frame.Side);
            return forward == 0 && side == 0 ? 0 : PortableMath.Atan2(side, forward) * (180 / Math.PI);
        }

        /// <summary>The launch state at <paramref name="position"/>: the solved velocity and spin.</summary>
        /// <param name="position">The launch point, m.</param>
        /// <param name="time">The launch time, s.</param>
        public FlightState LaunchState(in Vector3d position, double time = 0) => new FlightState(position, Velocity, AngularVelocity, time);

        /// <inheritdoc />
        public override string ToString() =>
            $"{Status}: speed {Speed:R} m/s, elevation {ElevationDegrees:R} deg, azimuth from target {AzimuthFromTargetDegrees:R} deg, miss {Miss:R} m, {Simulations} flights";
    }
}
