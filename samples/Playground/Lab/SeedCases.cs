using System;
using MagnusBall.Aerodynamics;
using MagnusBall.Flight;
using MagnusBall.Integration;
using MagnusBall.Queries;

namespace MagnusBall.Playground.Lab
{
    /// <summary>One row of a seed case: what was asked, what was published, what the library gives, and its flight.</summary>
    public sealed class SeedRow
    {
        /// <summary>The row's name.</summary>
        public string Name { get; set; } = string.Empty;

        /// <summary>The published value (degrees or metres), NaN if none.</summary>
        public double Published { get; set; } = double.NaN;

        /// <summary>The library's value, same unit.</summary>
        public double Value { get; set; }

        /// <summary>A second library value where the row has one (the free kicks' height at the goal line), NaN if none.</summary>
        public double Second { get; set; } = double.NaN;

        /// <summary>The free kick reached the goal line (it did not land short).</summary>
        public bool ReachedGoalLine { get; set; }

        /// <summary>Where the flight ended, downrange, m.</summary>
        public double Downrange { get; set; }

        /// <summary>The flight, sampled at every step.</summary>
        public Vector3d[] Path { get; set; } = Array.Empty<Vector3d>();
    }

    /// <summary>
    /// The seed thesis's own checks, as the library's validation tests run them (tests/MagnusBall.Tests/Validation):
    /// Cross (2011)'s four minimum angles of a 30 m/s tennis ball from 1 m (clear the 0.914 m net at 11.885 m, reach
    /// the baseline at 23.77 m; no spin and 20 rev/s topspin), and Javorova &amp; Ivanov (2018)'s three free kicks
    /// (19.32, 24.15 and 28.91 m/s, 61.86 rad/s of sidespin, aimed at 3.2 m across and 2.2 m up on the goal line 20 m
    /// away). The numbers and the published values are those of data/published/cross2011_tennis.json and
    /// javorova2018_freekick.json.
    /// </summary>
    public static class SeedCases
    {
        /// <summary>The step of every seed flight: RK4 at 1/240 s, as in the validation tests.</summary>
        public const double Step = 1.0 / 240;

        /// <summary>Cross's four minimum angles, degrees, with Stepanek's drag and lift: net no spin, baseline no spin, net topspin, baseline topspin.</summary>
        public static SeedRow[] CrossAngles()
        {
            var model = new FlightModel(new Ball(0.057, 0.033), new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance);
            var solver = new AimSolver(model, RungeKutta4.Instance, Step, Plane.Ground(model));
            var start = new Vector3d(0, 0, 1.0);
            var net = new Plane(new Vector3d(11.885, 0, 0), Vector3d.UnitX);
            var baseline = new Vector3d(23.77, 0, 0);
            var topspin = new LaunchSpin(Spin.FromRevolutionsPerSecond(20));
            AimSolution[] solutions =
            {
                solver.MinimumElevationToClear(start, 30, 0, LaunchSpin.None, net, 0.914),
                solver.ElevationToReach(start, 30, LaunchSpin.None, baseline),
                solver.MinimumElevationToClear(start, 30, 0, topspin, net, 0.914),
                solver.ElevationToReach(start, 30, topspin, baseline),
            };
            string[] names = { "clear the net, no spin", "reach the baseline, no spin", "clear the net, 20 rev/s topspin", "reach the baseline, 20 rev/s topspin" };
            double[] published = { 4.0, 8.1, 5.5, 11.9 };
            var predictor = new TrajectoryPredictor(model, RungeKutta4.Instance, Step);
            var rows = new SeedRow[4];
            for (int i = 0; i < 4; i++)
            {
                rows[i] = new SeedRow
                {
                    Name = names[i],
                    Published = published[i],
                    Value = solutions[i].IsSolved ? solutions[i].ElevationDegrees : double.NaN,
                    Path = solutions[i].IsSolved ? PathOf(predictor, solutions[i].LaunchState(start), FlightEventKinds.Landing, out _) : Array.Empty<Vector3d>(),
                };
            }

            return rows;
        }

        /// <summary>
        /// Javorova &amp; Ivanov's three kicks, launched at the angles that take the 24.15 m/s kick to the target:
        /// each row's <see cref="SeedRow.Value"/> is the distance across where the flight ends (at the goal line, or where
        /// it lands short of it: <see cref="SeedRow.ReachedGoalLine"/>), m, and <see cref="SeedRow.Second"/> the height
        /// there, m (the target: 3.2 m across, 2.2 m up).
        /// </summary>
        public static SeedRow[] FreeKicks()
        {
            var ball = new Ball(0.425, 0.11, Ball.ThinShellInertiaFactor);
            var model = new FlightModel(ball, new Air(1.21), Gravity.ZUp, GoffCarreSoccerDrag.Instance, PiecewiseLinearLift.SoccerGoffCarre);
            Vector3d start = new Vector3d(0, 0, ball.Radius);
            var ground = new Plane(start, Vector3d.UnitZ);
            var target = new Vector3d(20, 3.2, 2.2);
            var spin = new LaunchSpin(0, 61.86);
            var solver = new AimSolver(model, RungeKutta4.Instance, Step, ground);
            AimSolution aim = solver.AnglesToReach(start, 24.15, spin, target);
            double[] speeds = { 19.32, 24.15, 28.91 };
            var rows = new SeedRow[3];
            var frame = new LaunchFrame(Vector3d.UnitZ, target - start);
            var goal = new Plane(new Vector3d(20, 0, 0), Vector3d.UnitX);
            var predictor = new TrajectoryPredictor(model, RungeKutta4.Instance, Step, new FlightEventSet(Vector3d.UnitZ, ground, new[] { goal }));
            for (int i = 0; i < 3; i++)
            {
                var row = new SeedRow { Name = $"{speeds[i]} m/s" };
                if (aim.IsSolved)
                {
                    Vector3d direction = frame.Direction(aim.ElevationRadians, aim.AzimuthFromTargetRadians);
                    var launch = new FlightState(start, direction * speeds[i], spin.AngularVelocity(direction, frame));
                    row.Path = PathOf(predictor, launch, FlightEventKinds.Landing | FlightEventKinds.PlaneCrossing, out Prediction p);
                    row.ReachedGoalLine = p.StopEvent.Kind == FlightEventKinds.PlaneCrossing;
                    row.Downrange = p.EndState.Position.X;
                    row.Value = p.EndState.Position.Y;
                    row.Second = p.EndState.Position.Z;
                }
                else
                {
                    row.Value = double.NaN;
                }

                rows[i] = row;
            }

            return rows;
        }

        /// <summary>The flight's sampled path to its first event of <paramref name="stopAt"/> (at most 10 s), and the prediction.</summary>
        private static Vector3d[] PathOf(TrajectoryPredictor predictor, in FlightState launch, FlightEventKinds stopAt, out Prediction prediction)
        {
            var samples = new Vector3d[4096];
            prediction = predictor.Predict(launch, 10, samples, stopAt);
            return samples.AsSpan(0, prediction.SampleCount).ToArray();
        }
    }
}
