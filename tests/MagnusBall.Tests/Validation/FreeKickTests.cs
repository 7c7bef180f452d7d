using System;
using System.Text.Json;
using MagnusBall.Flight;
using MagnusBall.Aerodynamics;
using MagnusBall.Integration;
using MagnusBall.Queries;
using NUnit.Framework;

namespace MagnusBall.Tests.Validation
{
    /// <summary>
    /// Javorova &amp; Ivanov (2018), "Study of soccer ball flight trajectory", MATEC Web Conf. 145:01002, as
    /// quoted by the seed thesis: three free kicks from 20 m with the same launch angles and 61.86 rad/s
    /// sidespin at 19.32, 24.15 and 28.91 m/s; only the middle one scores, near (3.2 m to the side, 2.2 m
    /// high) at the goal line. Data: data/published/javorova2018_freekick.json.
    /// </summary>
    [TestFixture]
    [Category("Validation")]
    public class FreeKickTests
    {
        private JsonElement _published;

        [OneTimeSetUp]
        public void Load() => _published = PublishedCases.Load("javorova2018_freekick.json");

        /// <summary>One frame's view of the case: gravity, up, forward (toward goal) and side (toward the target).</summary>
        internal readonly struct Frame
        {
            public Frame(string name, Vector3d up, Vector3d forward)
            {
                Name = name;
                Up = up;
                Forward = forward;
                Side = new LaunchFrame(up, forward).Side;
            }

            public string Name { get; }
            public Vector3d Up { get; }
            public Vector3d Forward { get; }
            public Vector3d Side { get; }

            public Vector3d Point(double forward, double side, double up) => Forward * forward + Side * side + Up * up;
        }

        internal readonly struct Kick
        {
            public Kick(AimSolution aim, Prediction[] flights, double[] goalLineHeights, double[] goalLineSides, double[] landings)
            {
                Aim = aim;
                Flights = flights;
                GoalLineHeights = goalLineHeights;
                GoalLineSides = goalLineSides;
                Landings = landings;
            }

            public AimSolution Aim { get; }
            public Prediction[] Flights { get; }
            public double[] GoalLineHeights { get; }
            public double[] GoalLineSides { get; }
            public double[] Landings { get; }
        }

        internal Kick Run(Frame frame)
        {
            var ball = new Ball(_published.Number("ball", "mass_kg"), _published.Number("ball", "radius_m"), Ball.ThinShellInertiaFactor);
            // Soccer coefficients from the literature, not fitted to this case (docs/references.md
            // section 2): Goff & Carre (2010, Eur. J. Phys. 31:775) drag, the larger of their no-spin drag-crisis
            // curve and their spinning-ball fit 0.4127 S^0.3056 (here S ~ 0.25-0.4, so the spin fit, C_D ~ 0.27-0.30);
            // lift interpolated in the Teamgeist trajectory-analysis table and Goff & Carre (2009) (C_L ~ 0.29 here).
            // Air 1.21 kg/m^3 as in the thesis's Cross case (J&I's density is not quoted); no spin decay.
            var model = new FlightModel(
                ball, new Air(1.21), Gravity.Along(frame.Up), GoffCarreSoccerDrag.Instance, PiecewiseLinearLift.SoccerGoffCarre);

            // The ball rests on the pitch, so its centre starts one radius up, and it is "on the ground" when its
            // centre comes back down to that height.
            double r = ball.Radius;
            Vector3d start = frame.Point(0, 0, r);
            var ground = new Plane(start, frame.Up);
            double goalLine = _published.Number("goal_line_distance_m");
            Vector3d target = frame.Point(goalLine, _published.Number("target_at_goal_line", "lateral_m"), _published.Number("target_at_goal_line", "height_m"));
            var spin = new LaunchSpin(0, _published.Number("spin_radps")); // pure sidespin, curving toward the target's side

            // RK4 at 1/240 s; events on the Hermite are good to 1e-10 m at this step.
            var solver = new AimSolver(model, RungeKutta4.Instance, 1.0 / 240, ground);
            double[] speeds = { _published.GetProperty("speeds_mps")[0].GetDouble(), _published.GetProperty("speeds_mps")[1].GetDouble(), _published.GetProperty("speeds_mps")[2].GetDouble() };
            AimSolution aim = solver.AnglesToReach(start, speeds[1], spin, target);
            Assert.That(aim.IsSolved, Is.True, "the 24.15 m/s kick can be aimed at the target");

            var launchFrame = new LaunchFrame(frame.Up, target - start);
            Vector3d direction = launchFrame.Direction(aim.ElevationRadians, aim.AzimuthFromTargetRadians);
            var goalPlane = new Plane(frame.Point(goalLine, 0, 0), frame.Forward);
            var predictor = new TrajectoryPredictor(model, RungeKutta4.Instance, 1.0 / 240, new FlightEventSet(frame.Up, ground, new[] { goalPlane }));

            var flights = new Prediction[3];
            var heights = new double[3];
            var sides = new double[3];
            var landings = new double[3];
            for (int i = 0; i < 3; i++)
            {
                var launch = new FlightState(start, direction * speeds[i], spin.AngularVelocity(direction, launchFrame));
                flights[i] = predictor.Predict(launch, 10, Span<Vector3d>.Empty, FlightEventKinds.Landing | FlightEventKinds.PlaneCrossing);
                Assert.That(flights[i].Stopped, Is.True);
                Vector3d p = flights[i].EndState.Position - frame.Point(0, 0, 0);
                heights[i] = Vector3d.Dot(p, frame.Up);
                sides[i] = Vector3d.Dot(p, frame.Side);
                landings[i] = Vector3d.Dot(p, frame.Forward);
            }

            return new Kick(aim, flights, heights, sides, landings);
        }

        private static readonly Frame ZUp = new Frame("z-up", Vector3d.UnitZ, Vector3d.UnitX);

        // Right-handed y-up (Godot): the z-up case rotated -90 deg about x, (x, y, z) -> (x, z, -y).
        private static readonly Frame YUp = new Frame("y-up", Vector3d.UnitY, Vector3d.UnitX);

        [Test]
        public void OnlyTheMiddleKickScores()
        {
            Kick kick = Run(ZUp);
            double crossbar = _published.Number("goal", "crossbar_m");
            double goalLine = _published.Number("goal_line_distance_m");
            string[] speeds = { "19.32", "24.15", "28.91" };

            TestContext.Out.WriteLine($"aim: {kick.Aim}");
            TestContext.Out.WriteLine($"launch velocity at 24.15 m/s: {kick.Aim.Velocity}, spin {kick.Aim.AngularVelocity} (z-up, x toward goal, target at +y)");
            TestContext.Out.WriteLine($"{"kick",-10}{"J&I 2018",-26}{"thesis",-22}MagnusBall (Goff & Carre coefficients, RK4 1/240 s)");
            for (int i = 0; i < 3; i++)
            {
                string published = i == 1 ? "scores, ~(3.2, 2.2) m" : "misses";
                string thesis = i == 1 ? "scores, (3.3, 2.1) m" : "misses";
                FlightEvent e = kick.Flights[i].StopEvent;
                string ours = e.Kind == FlightEventKinds.Landing
                    ? $"lands at {kick.Landings[i]:F2} m, {kick.GoalLineSides[i]:F2} m to the side, t {e.Time:F3} s"
                    : $"goal line at ({kick.GoalLineSides[i]:F3} m side, {kick.GoalLineHeights[i]:F3} m high), t {e.Time:F3} s";
                TestContext.Out.WriteLine($"{speeds[i],-10}{published,-26}{thesis,-22}{ours}");
            }

            // The 24.15 m/s kick through the target: 1 cm is the issue's bound (the solver itself converges to ~1e-7 m).
            Assert.That(kick.Flights[1].StopEvent.Kind, Is.EqualTo(FlightEventKinds.PlaneCrossing));
            Assert.That(kick.GoalLineSides[1], Is.EqualTo(_published.Number("target_at_goal_line", "lateral_m")).Within(0.01));
            Assert.That(kick.GoalLineHeights[1], Is.EqualTo(_published.Number("target_at_goal_line", "height_m")).Within(0.01));

            // 19.32 m/s: on the ground before the goal line.
            Assert.That(kick.Flights[0].StopEvent.Kind, Is.EqualTo(FlightEventKinds.Landing));
            Assert.That(kick.Landings[0], Is.LessThan(goalLine));

            // 28.91 m/s: over the crossbar at the goal line (centre above the bar's 2.44 m).
            Assert.That(kick.Flights[2].StopEvent.Kind, Is.EqualTo(FlightEventKinds.PlaneCrossing));
            Assert.That(kick.GoalLineHeights[2], Is.GreaterThan(crossbar));
        }

        [Test]
        public void YUpFrame_GivesTheSameNumbers()
        {
            Kick z = Run(ZUp);
            Kick y = Run(YUp);
            TestContext.Out.WriteLine($"z-up aim: {z.Aim}");
            TestContext.Out.WriteLine($"y-up aim: {y.Aim}");

            // The same computation in rotated coordinates: differences are rounding, amplified by the solver's
            // 1e-8 rad tolerance over 20 m (2e-7 m); 1e-6 deg and 1e-5 m leave room for that and nothing else.
            Assert.That(y.Aim.ElevationDegrees, Is.EqualTo(z.Aim.ElevationDegrees).Within(1e-6));
            Assert.That(y.Aim.AzimuthFromTargetDegrees, Is.EqualTo(z.Aim.AzimuthFromTargetDegrees).Within(1e-6));
            for (int i = 0; i < 3; i++)
            {
                Assert.That(y.Flights[i].StopEvent.Kind, Is.EqualTo(z.Flights[i].StopEvent.Kind));
                Assert.That(y.GoalLineHeights[i], Is.EqualTo(z.GoalLineHeights[i]).Within(1e-5));
                Assert.That(y.GoalLineSides[i], Is.EqualTo(z.GoalLineSides[i]).Within(1e-5));
                Assert.That(y.Landings[i], Is.EqualTo(z.Landings[i]).Within(1e-5));
            }

            // And the side really is the rotated +y: -z in this y-up frame.
            Assert.That(YUp.Side.Z, Is.EqualTo(-1).Within(1e-15));
        }
    }
}
