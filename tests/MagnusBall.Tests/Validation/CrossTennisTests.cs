using System;
using System.Text.Json;
using MagnusBall.Aerodynamics;
using MagnusBall.Integration;
using MagnusBall.Queries;
using NUnit.Framework;

namespace MagnusBall.Tests.Validation
{
    /// <summary>
    /// Cross (2011), "Ball trajectories" (Physics of Baseball &amp; Softball, Springer), as quoted by the seed
    /// thesis: minimum launch angles of a 30 m/s tennis ball from 1.0 m to clear the net (0.914 m at
    /// 11.885 m) and to reach the baseline (23.77 m), without spin and with 20 rev/s topspin.
    /// Data: data/published/cross2011_tennis.json.
    /// </summary>
    [TestFixture]
    [Category("Validation")]
    public class CrossTennisTests
    {
        private static readonly string[] Cases = { "net_nospin", "baseline_nospin", "net_topspin", "baseline_topspin" };

        private JsonElement _published;

        [OneTimeSetUp]
        public void Load() => _published = PublishedCases.Load("cross2011_tennis.json");

        private FlightModel Model(IDragModel drag, ILiftModel lift) => new FlightModel(
            new Ball(_published.Number("ball", "mass_kg"), _published.Number("ball", "radius_m")),
            new Air(_published.Number("air", "density_kgpm3")),
            Gravity.ZUp, drag, lift);

        // RK4 at 1/240 s: its landing error is below 1e-10 m (EventLocationTests), so the angles below are the
        // model's, not the integrator's.
        private AimSolver Solver(FlightModel model) => new AimSolver(model, RungeKutta4.Instance, 1.0 / 240, Plane.Ground(model));

        /// <summary>The four minimum angles, degrees, in the order of <see cref="Cases"/>.</summary>
        internal double[] Angles(FlightModel model)
        {
            AimSolver solver = Solver(model);
            var start = new Vector3d(0, 0, _published.Number("launch", "height_m"));
            double speed = _published.Number("launch", "speed_mps");
            var net = new Plane(new Vector3d(_published.Number("net", "distance_m"), 0, 0), Vector3d.UnitX);
            double netHeight = _published.Number("net", "height_m");
            var baseline = new Vector3d(_published.Number("baseline", "distance_m"), 0, 0);
            var topspin = new LaunchSpin(Spin.FromRevolutionsPerSecond(_published.Number("topspin_revps")));

            var result = new double[4];
            AimSolution[] solutions =
            {
                solver.MinimumElevationToClear(start, speed, 0, LaunchSpin.None, net, netHeight),
                solver.ElevationToReach(start, speed, LaunchSpin.None, baseline),
                solver.MinimumElevationToClear(start, speed, 0, topspin, net, netHeight),
                solver.ElevationToReach(start, speed, topspin, baseline),
            };
            for (int i = 0; i < 4; i++)
            {
                Assert.That(solutions[i].IsSolved, Is.True, Cases[i]);
                result[i] = solutions[i].ElevationDegrees;
            }

            TestContext.Out.WriteLine(
                $"flights per solve: {solutions[0].Simulations}, {solutions[1].Simulations}, {solutions[2].Simulations}, {solutions[3].Simulations}");

            return result;
        }

        private void Print(string title, double[] magnusBall)
        {
            TestContext.Out.WriteLine(title);
            TestContext.Out.WriteLine($"{"case",-18}{"Cross 2011",12}{"thesis",10}{"MagnusBall",12}");
            for (int i = 0; i < 4; i++)
            {
                TestContext.Out.WriteLine(
                    $"{Cases[i],-18}{_published.Number("published_min_angles_deg", Cases[i]),12:F1}{_published.Number("seed_thesis_angles_deg", Cases[i]),10:F1}{magnusBall[i],12:F3}");
            }
        }

        [Test]
        public void StepanekModel_MatchesCrossAngles()
        {
            double[] angles = Angles(Model(StepanekDrag.Instance, StepanekLift.Instance));
            Print("Stepanek (1988) C_D(S), C_L(S); RK4 1/240 s; no per-case tuning", angles);
            for (int i = 0; i < 4; i++)
            {
                // 0.25 deg: the issue's bound; Cross's angles are read from a book figure to 0.1 deg.
                Assert.That(angles[i], Is.EqualTo(_published.Number("published_min_angles_deg", Cases[i])).Within(0.25), Cases[i]);
            }
        }

        [Test]
        public void ThesisConstants_MatchThesisAngles()
        {
            double[] angles = Angles(Model(
                new ConstantDrag(_published.Number("seed_thesis_coefficients", "cd")), new ConstantLift(_published.Number("seed_thesis_coefficients", "cm"))));
            Print("thesis constants c_d 0.55, c_m 0.175; RK4 1/240 s", angles);
            for (int i = 0; i < 4; i++)
            {
                // 0.2 deg: the issue's bound; the thesis reports its angles to 0.1 deg from an Euler/RK4 search.
                Assert.That(angles[i], Is.EqualTo(_published.Number("seed_thesis_angles_deg", Cases[i])).Within(0.2), Cases[i]);
            }
        }

        [TestCase("cm_0.175_range_m", 0.175)]
        [TestCase("cm_0.15_range_m", 0.15)]
        public void ThesisRangeCheck(string field, double liftCoefficient)
        {
            FlightModel model = Model(new ConstantDrag(_published.Number("seed_thesis_coefficients", "cd")), new ConstantLift(liftCoefficient));
            double e = PublishedCases.Radians(_published.Number("seed_thesis_distance_check", "angle_deg"));
            double speed = _published.Number("launch", "speed_mps");
            var frame = new LaunchFrame(Vector3d.UnitZ, Vector3d.UnitX);
            Vector3d direction = frame.Direction(e, 0);
            var spin = new LaunchSpin(Spin.FromRevolutionsPerSecond(_published.Number("seed_thesis_distance_check", "topspin_revps")));
            var start = new FlightState(new Vector3d(0, 0, _published.Number("launch", "height_m")), direction * speed, spin.AngularVelocity(direction, frame));

            var predictor = new TrajectoryPredictor(model, RungeKutta4.Instance, 1.0 / 240);
            Prediction p = predictor.Predict(start, 10, Span<Vector3d>.Empty);
            double expected = _published.Number("seed_thesis_distance_check", field);
            TestContext.Out.WriteLine($"11.9 deg, 20 rev/s topspin, c_m {liftCoefficient}: thesis {expected} m, MagnusBall {p.EndState.Position.X:F3} m");
            Assert.That(p.Stopped, Is.True);
            // 0.2 m: the issue's bound; the thesis quotes these ranges to 1-2 cm from its own RK4 run.
            Assert.That(p.EndState.Position.X, Is.EqualTo(expected).Within(0.2));
        }
    }
}
