#nullable enable
using System;
using MagnusBall.Flight;
using MagnusBall.Contact;
using MagnusBall.Contact.Shapes;
using MagnusBall.Contact.Swings;
using MagnusBall.Queries;
using MagnusBall.Stepping;

namespace MagnusBall.Samples.TennisScene
{
    /// <summary>What one shot did: the numbers of one row of the scene's table.</summary>
    public sealed class ShotReport
    {
        internal ShotReport(
            TennisShot shot, double? netClearance, FlightEvent? firstBounce, Vector3d? secondBounce, double apexHeight, int pathCount,
            FlightEvent? netContact = null)
        {
            Shot = shot;
            NetClearance = netClearance;
            FirstBounce = firstBounce;
            SecondBounce = secondBounce;
            ApexHeight = apexHeight;
            PathCount = pathCount;
            NetContact = netContact;
            // A ball that touched the net went over it when it came down on the far side (x > 0).
            ClearedNet = netContact.HasValue
                ? netClearance.HasValue && Landed && Landing.X > 0
                : netClearance.HasValue && netClearance.Value > 0;
            IsIn = Landed && ClearedNet && TennisCourt.IsIn(shot.Target, Landing.X, Landing.Z);
            IsLet = IsIn && netContact.HasValue && ShotSimulation.IsCord(netContact.Value.ShapeId)
                && (shot.Target == TargetArea.FarDeuceServiceBox || shot.Target == TargetArea.FarAdServiceBox);
        }

        /// <summary>The ball's first touch of the net (its cord, mesh or a post: <see cref="ShotSimulation.Net"/>), or null.</summary>
        public FlightEvent? NetContact { get; }

        /// <summary>A let: a serve that touched the net cord and then landed in its service box (it is played again).</summary>
        public bool IsLet { get; }

        /// <summary>The shot.</summary>
        public TennisShot Shot { get; }

        /// <summary>
        /// How far the bottom of the ball passed above the net cord, m (negative: into the net); null if the
        /// ball never reached the net's plane.
        /// </summary>
        public double? NetClearance { get; }

        /// <summary>True when the whole ball passed above the net cord.</summary>
        public bool ClearedNet { get; }

        /// <summary>The first bounce (state before and after), or null when the ball never came down.</summary>
        public FlightEvent? FirstBounce { get; }

        /// <summary>The contact point of the second bounce on the court (y = 0), or null.</summary>
        public Vector3d? SecondBounce { get; }

        /// <summary>True when the ball came down on the court within the time limit.</summary>
        public bool Landed => FirstBounce.HasValue;

        /// <summary>The contact point on the court at the first bounce, m (y = 0; zero when it never landed).</summary>
        public Vector3d Landing => FirstBounce.HasValue ? OnCourt(FirstBounce.Value.Position) : Vector3d.Zero;

        /// <summary>Time from the hit to the first bounce, s.</summary>
        public double TimeOfFlight => FirstBounce.HasValue ? FirstBounce.Value.Time : double.PositiveInfinity;

        /// <summary>Speed arriving at the first bounce, m/s.</summary>
        public double SpeedAtBounce => FirstBounce.HasValue ? FirstBounce.Value.State.Velocity.Length : 0;

        /// <summary>Angle of descent at the first bounce, deg below the horizontal.</summary>
        public double DescentAngleDegrees => FirstBounce.HasValue ? -ElevationDegrees(FirstBounce.Value.State.Velocity) : 0;

        /// <summary>Speed leaving the first bounce, m/s.</summary>
        public double SpeedAfterBounce => FirstBounce.HasValue ? FirstBounce.Value.After.Velocity.Length : 0;

        /// <summary>Angle leaving the first bounce, deg above the horizontal.</summary>
        public double ReboundAngleDegrees => FirstBounce.HasValue ? ElevationDegrees(FirstBounce.Value.After.Velocity) : 0;

        /// <summary>Topspin leaving the first bounce, rpm (negative: backspin): the spin about the axis that topspin has for that direction of travel.</summary>
        public double TopspinAfterBounceRpm => FirstBounce.HasValue ? TopspinRpm(FirstBounce.Value.After) : 0;

        /// <summary>Whether the first bounce slid throughout or gripped.</summary>
        public BounceRegime BounceRegime => FirstBounce.HasValue ? FirstBounce.Value.Regime : BounceRegime.None;

        /// <summary>Highest height of the ball's centre above the court before the first bounce, m.</summary>
        public double ApexHeight { get; }

        /// <summary>True when the shot cleared the net and landed in its target area (lines count as in).</summary>
        public bool IsIn { get; }

        /// <summary>How many path points were written to the caller's buffer.</summary>
        public int PathCount { get; }

        private static Vector3d OnCourt(in Vector3d p) => new Vector3d(p.X, 0, p.Z);

        private static double ElevationDegrees(in Vector3d v) =>
            Math.Atan2(Vector3d.Dot(v, TennisCourt.Up), Math.Sqrt(v.X * v.X + v.Z * v.Z)) * (180 / Math.PI);

        private static double TopspinRpm(in FlightState state)
        {
            Vector3d horizontal = state.Velocity - TennisCourt.Up * Vector3d.Dot(state.Velocity, TennisCourt.Up);
            if (horizontal.LengthSquared == 0)
            {
                return 0;
            }

            // Spin.Topspin(v, up, n) = n normalize(v x -up): project the spin on that axis.
            Vector3d axis = Vector3d.Cross(horizontal, -TennisCourt.Up).NormalizedOrZero();
            return Spin.ToRpm(Vector3d.Dot(state.AngularVelocity, axis));
        }
    }

    /// <summary>
    /// Flies tennis shots through the library's <see cref="FixedStepDriver"/>, as the Unity ball does frame by
    /// frame, bouncing them on the court (Cross's bounce model through the library's BouncingFlight), and
    /// measures them. Shared by the Unity scripts and the headless runner.
    /// </summary>
    public sealed class ShotSimulation
    {
        /// <summary>The longest flight simulated, s.</summary>
        public const double MaxFlightSeconds = 15;

        private TrajectoryPredictor? _predictor;

        /// <summary>Creates a simulation with the given settings.</summary>
        /// <param name="settings">The ball, air, coefficients, court surface, integrator and fixed step.</param>
        public ShotSimulation(SceneSettings settings)
        {
            Settings = settings ?? throw new ArgumentNullException(nameof(settings));

            // The net as the library's contact shapes (SportShapes.TennisNet: the cord in two sagging halves, the mesh
            // and the posts, ids 0-4), so a ball that clips the tape is answered by it (a let, a net cord winner).
            Net = MagnusBall.Shots.SportShapes.TennisNet(NetFirstId, Vector3d.Zero, TennisCourt.Left, TennisCourt.Up);

            // The ground sits one ball radius above the court: the ball lands when it touches the court, not
            // when its centre reaches it. The net's plane (x = 0) is crossed along +x by a shot from the near side.
            Events = new FlightEventSet(
                TennisCourt.Up,
                new Plane(TennisCourt.Up * settings.Ball.Radius, TennisCourt.Up),
                new[] { new Plane(Vector3d.Zero, TennisCourt.Downrange) });
        }

        /// <summary>The first id of the net's shapes: cord (left half, right half), mesh, posts (<see cref="Net"/>).</summary>
        public const int NetFirstId = 0;

        /// <summary>The settings.</summary>
        public SceneSettings Settings { get; }

        /// <summary>The net, as contact shapes every ball of this scene can hit (MagnusBall.Shots.SportShapes.TennisNet).</summary>
        public ContactShape[] Net { get; }

        /// <summary>True for the id of one of the net cord's two halves.</summary>
        /// <param name="shapeId">A contact event's shape id.</param>
        public static bool IsCord(int shapeId) => shapeId == NetFirstId || shapeId == NetFirstId + 1;

        /// <summary>The bounce model, or null when flights end at the first landing.</summary>
        public IBounceModel? Bounce => Settings.Bounce;

        /// <summary>The events every ball of this scene watches: the court (one radius up), the apex and the net's plane (index 0).</summary>
        public FlightEventSet Events { get; }

        /// <summary>A driver for one ball of this scene.</summary>
        /// <param name="start">The launch state.</param>
        /// <param name="maxFrameDeltaSeconds">The frame-time clamp, s.</param>
        public FixedStepDriver CreateDriver(in FlightState start, double maxFrameDeltaSeconds = FixedStepDriver.DefaultMaxFrameDeltaSeconds) =>
            new FixedStepDriver(Settings.Model, Settings.Integrator, Settings.FixedStep, start, Events, Bounce, maxFrameDeltaSeconds, shapes: Net);

        /// <summary>The clearance of the bottom of the ball over the net cord where it crosses the net's plane, m.</summary>
        /// <param name="crossing">The ball's centre at the crossing, m.</param>
        public double NetClearance(in Vector3d crossing) => crossing.Y - Settings.Ball.Radius - TennisCourt.NetHeightAt(crossing.Z);

        /// <summary>
        /// Flies <paramref name="shot"/> to its second bounce (or rest, or the time limit) and measures it;
        /// writes the path (every fixed state and every bounce point) into <paramref name="path"/> as far as it holds.
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
            Span<FlightEvent> events = stackalloc FlightEvent[8];
            int count = 0;
            Append(path, ref count, driver.State.Position);
            double apex = driver.State.Position.Y;
            double? clearance = null;
            FlightEvent? first = null;
            FlightEvent? net = null;
            Vector3d? second = null;
            while (second == null && !driver.IsFinished && driver.State.Time < MaxFlightSeconds)
            {
                // One fixed step per call: the same steps any frame rate would give (see FixedStepDriver).
                AdvanceResult result = driver.Advance(Settings.FixedStep, events);
                for (int i = 0; i < result.EventCount; i++)
                {
                    FlightEvent e = events[i];
                    switch (e.Kind)
                    {
                        case FlightEventKinds.PlaneCrossing:
                            clearance ??= NetClearance(e.Position);
                            break;
                        case FlightEventKinds.Contact:
                            // The net: the path bends there.
                            Append(path, ref count, e.Position);
                            net ??= e;
                            break;
                        case FlightEventKinds.Apex:
                            if (first == null)
                            {
                                apex = Math.Max(apex, e.Position.Y);
                            }

                            break;
                        case FlightEventKinds.Bounce:
                        case FlightEventKinds.Landing: // the flight's end when the scene has no bounce model
                            Append(path, ref count, e.Position);
                            if (first == null)
                            {
                                first = e;
                            }
                            else if (second == null)
                            {
                                second = new Vector3d(e.Position.X, 0, e.Position.Z);
                            }

                            break;
                    }
                }

                if (second == null)
                {
                    Append(path, ref count, driver.State.Position);
                }
            }

            return new ShotReport(shot, clearance, first, second, apex, count, net);
        }

        /// <summary>
        /// Predicts the path from <paramref name="from"/> to the next landing (or the time limit) with the
        /// library's <see cref="TrajectoryPredictor"/>, writing every fixed step's position and the landing
        /// point into <paramref name="points"/>. It steps exactly as the ball's driver does, so the ball
        /// follows the prediction to the bit. Allocates nothing after the first call.
        /// </summary>
        /// <param name="from">The state to predict from.</param>
        /// <param name="points">Where to write the points, m.</param>
        /// <returns>How many points were written.</returns>
        public int Predict(in FlightState from, Span<Vector3d> points)
        {
            _predictor ??= new TrajectoryPredictor(Settings.Model, Settings.Integrator, Settings.FixedStep, Events);
            return _predictor.Predict(from, MaxFlightSeconds, points).SampleCount;
        }

        /// <summary>
        /// The same shot (speed, spin, hitting point) with its elevation and azimuth solved by the library's
        /// <see cref="AimSolver"/> so that it first touches the court at (<paramref name="x"/>, <paramref name="z"/>);
        /// null when no elevation in [-45, 80] deg and azimuth within 45 deg of the target direction does it.
        /// </summary>
        /// <param name="shot">The shot to aim.</param>
        /// <param name="x">Target contact point along the court, m.</param>
        /// <param name="z">Target contact point across the court, m.</param>
        public TennisShot? Aim(TennisShot shot, double x, double z)
        {
            if (shot == null)
            {
                throw new ArgumentNullException(nameof(shot));
            }

            var solver = new AimSolver(Settings.Model, Settings.Integrator, Settings.FixedStep, Events.Ground!.Value, MaxFlightSeconds);

            // LaunchSpin's side is normalize(up x forward): toward -z here (the hitter's right), so the shot's
            // sidespin toward +z is a negative LaunchSpin sidespin. Both build the spin by effect, so they agree.
            var spin = new LaunchSpin(Spin.FromRpm(shot.TopspinRpm), -Spin.FromRpm(shot.SidespinRpm));

            // The ball's centre touches down one radius above the contact point.
            var target = new Vector3d(x, 0, z) + TennisCourt.Up * Settings.Ball.Radius;
            AimSolution solution = solver.AnglesToReach(shot.Start, shot.Speed, spin, target);
            if (!solution.IsSolved)
            {
                return null;
            }

            // Back to the shot's own angles: elevation above the horizontal, azimuth from +x toward +z.
            Vector3d v = solution.Velocity;
            double elevation = Math.Asin(Vector3d.Dot(v, TennisCourt.Up) / v.Length) * (180 / Math.PI);
            double azimuth = Math.Atan2(Vector3d.Dot(v, TennisCourt.Left), Vector3d.Dot(v, TennisCourt.Downrange)) * (180 / Math.PI);
            return shot.WithAngles(elevation, azimuth);
        }

        /// <summary>
        /// The same swing (racket speed, path, face turn, impact point, incoming ball) with its face tilt and azimuth
        /// solved by the library's inverse (<see cref="SwingAim"/> on <see cref="AimSolver"/>) so that the ball first
        /// touches the court at (<paramref name="x"/>, <paramref name="z"/>); null when the swing cannot reach it.
        /// </summary>
        /// <param name="swing">The swing shot to aim; its face tilt and azimuth are the starting guess.</param>
        /// <param name="x">Target contact point along the court, m.</param>
        /// <param name="z">Target contact point across the court, m.</param>
        /// <param name="minimumElevationDegrees">The lowest launch elevation the aim solver tries, degrees (raise it for a lob, so it is not solved as a drive).</param>
        public TennisSwing? AimSwing(TennisSwing swing, double x, double z, double minimumElevationDegrees = -45)
        {
            if (swing == null)
            {
                throw new ArgumentNullException(nameof(swing));
            }

            var solver = new AimSolver(
                Settings.Model, Settings.Integrator, Settings.FixedStep, Events.Ground!.Value, MaxFlightSeconds, minimumElevationDegrees);
            var aim = new SwingAim(solver, Settings.Ball);
            var target = new Vector3d(x, 0, z) + TennisCourt.Up * Settings.Ball.Radius;
            SwingSolution<RacketSwing> result = aim.RacketFaceToReach(swing.Swing, TennisSwing.Frame, swing.Start, swing.IncomingVelocity, swing.IncomingSpin, target);
            return result.IsSolved ? swing.WithSwing(result.Swing) : null;
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
