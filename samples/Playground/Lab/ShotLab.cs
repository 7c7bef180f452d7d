using System;
using System.Collections.Generic;
using MagnusBall.Flight;
using MagnusBall.Integration;
using MagnusBall.Presets;
using MagnusBall.Queries;

namespace MagnusBall.Playground.Lab
{
    /// <summary>One flown shot: its path, its events and its numbers, or why it has none.</summary>
    public sealed class ShotResult
    {
        /// <summary>The path, sampled at every step and at the end (m; x downrange, y left, z up).</summary>
        public Vector3d[] Path { get; set; } = Array.Empty<Vector3d>();

        /// <summary>Events in time order (landing, apex, crossing of the obstacle plane).</summary>
        public List<FlightEvent> Events { get; } = new List<FlightEvent>();

        /// <summary>The first crossing of the scene's plane <paramref name="index"/>, or null.</summary>
        public FlightEvent? Crossing(int index)
        {
            foreach (FlightEvent e in Events)
            {
                if (e.Kind == FlightEventKinds.PlaneCrossing && e.PlaneIndex == index)
                {
                    return e;
                }
            }

            return null;
        }

        /// <summary>The flight reached the ground.</summary>
        public bool Landed { get; set; }

        /// <summary>The flight diverged (a step too long for the integrator): no landing is reported.</summary>
        public bool Diverged { get; set; }

        /// <summary>Where and when it ended (the landing, or where it was at the time limit).</summary>
        public FlightState End { get; set; }

        /// <summary>The highest point of the path.</summary>
        public Vector3d Apex { get; set; }

        /// <summary>
        /// Height of the ball's bottom over the obstacle where its centre crossed the obstacle's plane, m: the gap
        /// between ball and tape (negative: the ball touches or hits it); NaN if it did not cross.
        /// </summary>
        public double Clearance { get; set; } = double.NaN;

        /// <summary>The ball's radius, m.</summary>
        public double BallRadius { get; set; }

        /// <summary>
        /// The launch's step against the method's stability bound for the flight's drag: how many steps the method's
        /// check would split it into (1: within the bound). The check is the library's, StableIntegrator.AtStabilityBound (the
        /// CLI's too): h sigma at most 2 for the Euler methods and Heun, 2.5 for RK4 and Dormand-Prince.
        /// </summary>
        public int StabilityRatio { get; set; } = 1;

        /// <summary>The step is beyond the method's stability bound and the method does not split it: no result is shown.</summary>
        public bool Unreliable { get; set; }

        /// <summary>Steps taken.</summary>
        public long Steps { get; set; }

        /// <summary>Model evaluations made.</summary>
        public long Evaluations { get; set; }

        /// <summary>Distance of the landing from the reference flight's landing, m; NaN where either did not land.</summary>
        public double ReferenceError { get; set; } = double.NaN;

        /// <summary>Speed at the end, m/s.</summary>
        public double EndSpeed => End.Velocity.Length;

        /// <summary>Descent angle at the landing below the horizontal, degrees.</summary>
        public double LandingAngleDegrees
        {
            get
            {
                Vector3d v = End.Velocity;
                double horizontal = Math.Sqrt(v.X * v.X + v.Y * v.Y);
                return Math.Atan2(-v.Z, horizontal) * (180 / Math.PI);
            }
        }
    }

    /// <summary>
    /// Flies the playground's shots with the library, in a z-up frame (x downrange, y to the left): the preset's model
    /// in the chosen air, the chosen integrator at the chosen fixed step, the landing and the obstacle crossing
    /// located on each step's dense output by <see cref="TrajectoryPredictor"/>.
    /// </summary>
    public static class ShotLab
    {
        /// <summary>The reference every shot's landing is compared with: RK4 at 1/8192 s (docs/accuracy-vs-speed.md).</summary>
        public const double ReferenceStep = 1.0 / 8192;

        /// <summary>The most samples kept for drawing; a longer path is thinned evenly.</summary>
        public const int MaximumPathPoints = 1500;

        /// <summary>The launch frame: up z, forward x, side y (left).</summary>
        public static readonly LaunchFrame Frame = new LaunchFrame(Vector3d.UnitZ, Vector3d.UnitX);

        /// <summary>The model the settings describe: the preset's ball and laws in their air.</summary>
        /// <exception cref="ArgumentException">A setting is out of the library's range (the message names it).</exception>
        public static FlightModel Model(ShotSettings s)
        {
            var wind = new Vector3d(s.TailwindMetresPerSecond, s.CrosswindMetresPerSecond, 0);
            Air air = Air.AtAltitude(s.AltitudeMetres, s.TemperatureCelsius, s.HumidityPercent / 100, wind);
            return SportPresets.FromName(s.Preset).CreateModel(air, Gravity.ZUp);
        }

        /// <summary>The launch state the settings describe.</summary>
        public static FlightState Launch(ShotSettings s)
        {
            Vector3d direction = Frame.Direction(s.ElevationDegrees * (Math.PI / 180), s.DirectionDegrees * (Math.PI / 180));
            var spin = new LaunchSpin(Spin.FromRpm(s.TopspinRpm), Spin.FromRpm(s.SidespinRpm));
            return new FlightState(new Vector3d(0, 0, s.LaunchHeightMetres), direction * s.SpeedMetresPerSecond, spin.AngularVelocity(direction, Frame));
        }

        /// <summary>Flies the shot with its integrator and step, and its reference.</summary>
        /// <exception cref="ArgumentException">A setting is out of the library's range (the message names it).</exception>
        public static ShotResult Fly(ShotSettings s) => Fly(s, s.Integrator, s.StepSeconds, withReference: true);

        /// <summary>The second shot the settings ask for, or null for none.</summary>
        public static ShotResult? FlyComparison(ShotSettings s)
        {
            switch (s.Compare)
            {
                case CompareWith.NoSpin:
                    ShotSettings plain = s.Clone();
                    plain.TopspinRpm = 0;
                    plain.SidespinRpm = 0;
                    return Fly(plain, plain.Integrator, plain.StepSeconds, withReference: true);
                case CompareWith.OtherIntegrator:
                    return Fly(s, s.CompareIntegrator, s.CompareStepSeconds, withReference: true);
                default:
                    return null;
            }
        }

        /// <summary>
        /// Aims the shot at a point on the ground: the elevation and direction that land it there at its speed and
        /// spin (the library's adaptive aim solver), or null with <paramref name="why"/> if none does.
        /// </summary>
        public static ShotSettings? AimAt(ShotSettings s, double targetX, double targetY, out string why)
        {
            FlightModel model = Model(s);
            var solver = new AimSolver(model, Plane.Ground(model));
            var spin = new LaunchSpin(Spin.FromRpm(s.TopspinRpm), Spin.FromRpm(s.SidespinRpm));
            AimSolution aim = solver.AnglesToReach(new Vector3d(0, 0, s.LaunchHeightMetres), s.SpeedMetresPerSecond, spin, new Vector3d(targetX, targetY, 0));
            if (!aim.IsSolved)
            {
                why = $"No launch at {s.SpeedMetresPerSecond:0.##} m/s with this spin lands at ({targetX:0.##}, {targetY:0.##}) m: {aim.Status} (miss {aim.Miss:0.###} m). Try another speed.";
                return null;
            }

            Vector3d v = aim.Velocity;
            ShotSettings aimed = s.Clone();
            aimed.ElevationDegrees = Math.Asin(v.Z / v.Length) * (180 / Math.PI);
            aimed.DirectionDegrees = Math.Atan2(v.Y, v.X) * (180 / Math.PI);
            why = string.Empty;
            return aimed;
        }

        private static ShotResult Fly(ShotSettings s, string integratorName, double step, bool withReference)
        {
            FlightModel model = Model(s);
            Scene scene = Scene.For(s.Preset);
            var events = FlightEventSet.ForModel(model, scene.Planes);
            FlightState start = Launch(s);
            IIntegrator integrator = Integrators.FromName(integratorName);
            ShotResult result = Run(new TrajectoryPredictor(model, integrator, step, events), start, s.MaxFlightSeconds, scene);
            result.BallRadius = model.Ball.Radius;
            if (double.IsFinite(result.Clearance))
            {
                result.Clearance -= model.Ball.Radius;
            }

            StableIntegrator? bound = StableIntegrator.AtStabilityBound(integrator);
            result.StabilityRatio = bound is null ? 1 : bound.SubstepCount(model, start, step);
            result.Unreliable = result.StabilityRatio > 1;
            if (withReference && result.Landed)
            {
                FlightState? landing = ReferenceLanding(s, model, events, start, scene);
                if (landing is FlightState l)
                {
                    result.ReferenceError = (result.End.Position - l.Position).Length;
                }
            }

            return result;
        }

        // The reference landing depends on the launch and the air, not on the integrator or its rate: the last few are
        // kept, keyed by every other setting, so changing the method, its rate or the second shot's does not fly the
        // long reference again.
        private static readonly Dictionary<string, FlightState?> References = new Dictionary<string, FlightState?>();

        private static FlightState? ReferenceLanding(ShotSettings s, FlightModel model, FlightEventSet events, in FlightState start, Scene scene)
        {
            ShotSettings key = s.Clone();
            key.Integrator = "rk4";
            key.StepsPerSecond = 240;
            key.Compare = CompareWith.None;
            key.CompareIntegrator = "rk4";
            key.CompareStepsPerSecond = 240;
            string query = key.ToQuery() + "&t=" + ShotSettings.Format(s.MaxFlightSeconds);
            if (!References.TryGetValue(query, out FlightState? landing))
            {
                ShotResult reference = Run(new TrajectoryPredictor(model, RungeKutta4.Instance, ReferenceStep, events), start, s.MaxFlightSeconds, scene);
                landing = reference.Landed ? reference.End : (FlightState?)null;
                if (References.Count >= 16)
                {
                    References.Clear();
                }

                References[query] = landing;
            }

            return landing;
        }

        private static ShotResult Run(TrajectoryPredictor predictor, in FlightState start, double maxSeconds, Scene scene)
        {
            int capacity = (int)Math.Min(maxSeconds / predictor.Step + 3, 200_000);
            var samples = new FlightState[capacity];
            var events = new FlightEvent[64];
            Prediction p = predictor.Predict(start, maxSeconds, samples, events, FlightEventKinds.Landing);
            var result = new ShotResult
            {
                Landed = p.Stopped,
                Diverged = p.Diverged,
                End = p.EndState,
                Steps = p.Steps,
                Evaluations = p.DerivativeEvaluations,
            };
            for (int i = 0; i < p.EventCount; i++)
            {
                result.Events.Add(events[i]);
                if (events[i].Kind == FlightEventKinds.PlaneCrossing && events[i].PlaneIndex == 0 && scene.ObstacleHeight > 0 && double.IsNaN(result.Clearance))
                {
                    result.Clearance = events[i].Position.Z - scene.ObstacleHeight;
                }
            }

            int count = p.SampleCount;
            int stride = Math.Max(1, (count + MaximumPathPoints - 1) / MaximumPathPoints);
            var path = new List<Vector3d>(count / stride + 2);
            Vector3d apex = start.Position;
            for (int i = 0; i < count; i++)
            {
                Vector3d q = samples[i].Position;
                if (q.Z > apex.Z)
                {
                    apex = q;
                }

                if (i % stride == 0 || i == count - 1)
                {
                    path.Add(q);
                }
            }

            foreach (FlightEvent e in result.Events)
            {
                if (e.Kind == FlightEventKinds.Apex && e.Position.Z > apex.Z)
                {
                    apex = e.Position;
                }
            }

            result.Apex = apex;
            result.Path = path.ToArray();
            return result;
        }
    }
}
