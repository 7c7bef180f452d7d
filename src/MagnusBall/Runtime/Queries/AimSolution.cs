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
        /// The solve stopped at its work cap (<see cref="AimSolver.MaxEvaluationsPerSolve"/> model evaluations plus steps) before it
        /// could decide; the launch fields hold where it was. Fly shorter trials (a smaller maximumFlightTime), a larger
        /// step or a coarser scan.
        /// </summary>
        WorkLimitReached = 2,
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
        /// <param name="azimuthRadians">Launch azimuth from the frame's forward toward its side, rad.</param>
        /// <param name="velocity">Launch velocity, m/s (world frame).</param>
        /// <param name="angularVelocity">Launch angular velocity, rad/s (world frame).</param>
        /// <param name="arrival">The solved shot's state where it crosses the target or obstacle plane.</param>
        /// <param name="miss">See <see cref="Miss"/>.</param>
        /// <param name="simulations">Flights simulated.</param>
        internal AimSolution(
            AimStatus status, double speed, double elevationRadians, double azimuthRadians, in Vector3d velocity, in Vector3d angularVelocity,
            in FlightState arrival, double miss, int simulations)
        {
            Status = status;
            Speed = speed;
            ElevationRadians = elevationRadians;
            AzimuthRadians = azimuthRadians;
            Velocity = velocity;
            AngularVelocity = angularVelocity;
            Arrival = arrival;
            Miss = miss;
            Simulations = simulations;
        }

        /// <summary>Solved or unreachable. When unreachable, the other fields describe the best attempt or are zero.</summary>
        public readonly AimStatus Status;

        /// <summary>Launch speed, m/s.</summary>
        public readonly double Speed;

        /// <summary>Launch elevation above the horizontal, rad.</summary>
        public readonly double ElevationRadians;

        /// <summary>Launch azimuth about up, from the frame's forward toward its side, rad (see <see cref="LaunchFrame"/>).</summary>
        public readonly double AzimuthRadians;

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

        /// <summary>Launch azimuth, degrees.</summary>
        public double AzimuthDegrees => AzimuthRadians * (180 / Math.PI);

        /// <summary>The launch state at <paramref name="position"/>: the solved velocity and spin.</summary>
        /// <param name="position">The launch point, m.</param>
        /// <param name="time">The launch time, s.</param>
        public FlightState LaunchState(in Vector3d position, double time = 0) => new FlightState(position, Velocity, AngularVelocity, time);

        /// <inheritdoc />
        public override string ToString() =>
            $"{Status}: speed {Speed:R} m/s, elevation {ElevationDegrees:R} deg, azimuth {AzimuthDegrees:R} deg, miss {Miss:R} m, {Simulations} flights";
    }
}
