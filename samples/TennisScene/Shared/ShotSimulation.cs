#nullable enable
using System;
using MagnusBall.Stepping;

namespace MagnusBall.Samples.TennisScene
{
    /// <summary>What one shot did: the numbers of one row of the scene's table.</summary>
    public sealed class ShotReport
    {
        internal ShotReport(
            TennisShot shot, double? netClearance, bool landed, Vector3d landing, Vector3d landingVelocity, double timeOfFlight,
            double apexHeight, int pathCount)
        {
            Shot = shot;
            NetClearance = netClearance;
            Landed = landed;
            Landing = landing;
            LandingVelocity = landingVelocity;
            TimeOfFlight = timeOfFlight;
            ApexHeight = apexHeight;
            PathCount = pathCount;
            ClearedNet = netClearance.HasValue && netClearance.Value > 0;
            IsIn = landed && ClearedNet && TennisCourt.IsIn(shot.Target, landing.X, landing.Z);
        }

        /// <summary>The shot.</summary>
        public TennisShot Shot { get; }

        /// <summary>
        /// How far the bottom of the ball passed above the net cord, m (negative: into the net); null if the
        /// ball never reached the net's plane.
        /// </summary>
        public double? NetClearance { get; }

        /// <summary>True when the whole ball passed above the net cord.</summary>
        public bool ClearedNet { get; }

        /// <summary>True when the ball came down on the court's plane within the time limit.</summary>
        public bool Landed { get; }

        /// <summary>The contact point on the court at the first bounce, m (y = 0).</summary>
        public Vector3d Landing { get; }

        /// <summary>The ball's velocity at the first bounce, m/s.</summary>
        public Vector3d LandingVelocity { get; }

        /// <summary>Speed at the first bounce, m/s.</summary>
        public double SpeedAtBounce => LandingVelocity.Length;

        /// <summary>Angle of descent at the first bounce, deg below the horizontal.</summary>
        public double DescentAngleDegrees =>
            Math.Atan2(-LandingVelocity.Y, Math.Sqrt(LandingVelocity.X * LandingVelocity.X + LandingVelocity.Z * LandingVelocity.Z)) * 180 / Math.PI;

        /// <summary>Time from the hit to the first bounce (or to the time limit), s.</summary>
        public double TimeOfFlight { get; }

        /// <summary>Highest height of the ball's centre above the court, m.</summary>
        public double ApexHeight { get; }

        /// <summary>True when the shot cleared the net and landed in its target area (lines count as in).</summary>
        public bool IsIn { get; }

        /// <summary>How many path points were written to the caller's buffer.</summary>
        public int PathCount { get; }
    }

    /// <summary>
    /// Flies tennis shots through the library's <see cref="FixedStepDriver"/>, as the Unity ball does frame by
    /// frame, and measures them. Shared by the Unity scripts and the headless runner.
    /// </summary>
    public sealed class ShotSimulation
    {
        /// <summary>The longest flight simulated, s.</summary>
        public const double MaxFlightSeconds = 15;

        private readonly FlightPlane[] _planes;
        private FixedStepDriver? _predictor;

        /// <summary>Creates a simulation with the given settings.</summary>
        /// <param name="settings">The ball, air, coefficients, integrator and fixed step.</param>
        public ShotSimulation(SceneSettings settings)
        {
            Settings = settings ?? throw new ArgumentNullException(nameof(settings));
            _planes = new[] { NetPlane };
        }

        /// <summary>The settings.</summary>
        public SceneSettings Settings { get; }

        /// <summary>The net's vertical plane (x = 0), crossed along +x by a shot from the near side.</summary>
        public static FlightPlane NetPlane => new FlightPlane(Vector3d.Zero, TennisCourt.Downrange);

        /// <summary>
        /// The ground the driver lands on: one ball radius above the court, so the flight ends when the ball
        /// touches the court, not when its centre reaches it.
        /// </summary>
        public Vector3d GroundPoint => TennisCourt.Up * Settings.Ball.Radius;

        /// <summary>A driver for one ball of this scene, watching the net plane and the ground.</summary>
        /// <param name="start">The launch state.</param>
        public FixedStepDriver CreateDriver(in FlightState start) =>
            new FixedStepDriver(Settings.Model, Settings.Integrator, Settings.FixedStep, start, GroundPoint, _planes);

        /// <summary>
        /// Flies <paramref name="shot"/> to its first bounce and measures it; writes the path (every fixed
        /// state, then the landing) into <paramref name="path"/> as far as it holds.
        /// </summary>
        /// <param name="shot">The shot.</param>
        /// <param name="path">Where to write the path, m; may be empty.</param>
        public ShotReport Run(TennisShot shot, Span<Vector3d> path)
        {
            if (shot == null)
            {
                throw new ArgumentNullException(nameof(shot));
            }

            FixedStepDriver driver = CreateDriver(shot.Launch());
            Span<FrameEvent> events = stackalloc FrameEvent[4];
            int count = 0;
            Append(path, ref count, driver.State.Position);
            double apex = driver.State.Position.Y;
            double? clearance = null;
            FrameEvent landing = default;
            bool landed = false;
            while (!landed && driver.State.Time < MaxFlightSeconds)
            {
                // One fixed step per call: the same steps any frame rate would give (see FixedStepDriver).
                AdvanceResult result = driver.Advance(Settings.FixedStep, events);
                for (int i = 0; i < result.EventCount; i++)
                {
                    FrameEvent e = events[i];
                    if (e.Kind == FrameEventKind.PlaneCrossing && clearance == null)
                    {
                        clearance = e.Position.Y - Settings.Ball.Radius - TennisCourt.NetHeightAt(e.Position.Z);
                    }
                    else if (e.Kind == FrameEventKind.Landing)
                    {
                        landing = e;
                        landed = true;
                    }
                }

                apex = Math.Max(apex, driver.State.Position.Y);
                Append(path, ref count, driver.State.Position);
            }

            FlightState end = landed ? landing.State : driver.State;
            Vector3d contact = new Vector3d(end.Position.X, 0, end.Position.Z);
            return new ShotReport(shot, clearance, landed, contact, end.Velocity, end.Time, apex, count);
        }

        /// <summary>
        /// Predicts the path from <paramref name="from"/> to the landing (or the time limit), writing one point
        /// every <paramref name="sampleInterval"/> seconds and the landing point into <paramref name="points"/>.
        /// Steps exactly as the ball's driver does, so the ball follows the prediction. Allocates nothing after
        /// the first call.
        /// </summary>
        /// <param name="from">The state to predict from.</param>
        /// <param name="points">Where to write the points, m.</param>
        /// <param name="sampleInterval">Time between points, s; finite and &gt; 0.</param>
        /// <returns>How many points were written.</returns>
        public int Predict(in FlightState from, Span<Vector3d> points, double sampleInterval)
        {
            if (!(sampleInterval > 0) || double.IsInfinity(sampleInterval))
            {
                throw new ArgumentOutOfRangeException(nameof(sampleInterval), sampleInterval, $"sampleInterval must be finite and > 0 s; got {sampleInterval}.");
            }

            if (_predictor == null)
            {
                _predictor = CreateDriver(from);
            }
            else
            {
                _predictor.Reset(from);
            }

            int count = 0;
            Append(points, ref count, from.Position);
            double next = from.Time + sampleInterval;
            double end = from.Time + MaxFlightSeconds;
            while (count < points.Length && !_predictor.HasLanded && _predictor.State.Time < end)
            {
                _predictor.Advance(Settings.FixedStep);
                if (_predictor.State.Time >= next || _predictor.HasLanded)
                {
                    Append(points, ref count, _predictor.State.Position);
                    while (next <= _predictor.State.Time)
                    {
                        next += sampleInterval;
                    }
                }
            }

            return count;
        }

        private static void Append(Span<Vector3d> path, ref int count, in Vector3d point)
        {
            if (count < path.Length)
            {
                path[count++] = point;
            }
        }
    }
}
