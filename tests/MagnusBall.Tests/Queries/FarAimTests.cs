using System;
using MagnusBall.Integration;
using MagnusBall.Queries;
using NUnit.Framework;

namespace MagnusBall.Tests.Queries
{
    /// <summary>
    /// Aim solves whose launch point, target, plane or ground point lie near 1e308 m apart (finite input whose differences
    /// overflow a double): the rules ask for a documented result, never NaN and never an undocumented exception. Where the
    /// far part only moves the problem along a direction nothing depends on, the answer is the near problem's, bit for bit.
    /// </summary>
    [TestFixture]
    public class FarAimTests
    {
        private static readonly FlightModel Model = Shots.StepanekTennis(Gravity.ZUp);
        private static readonly LaunchSpin Topspin = new LaunchSpin(Spin.FromRpm(1200), Spin.FromRpm(300));

        private static AimSolver Solver(bool adaptive, Plane ground) =>
            adaptive ? new AimSolver(Model, ground) : new AimSolver(Model, RungeKutta4.Instance, 1.0 / 120, ground);

        // The far solve is solved like the near one: to AimSolver.AngleTolerance with adaptive trials (their error control
        // weighs the far coordinate by its size), bit for bit in elevation and miss with fixed steps. True when the
        // comparison was exact (the caller may then compare more).
        private static bool AssertSolvedAsNear(in AimSolution far, in AimSolution near, bool adaptive)
        {
            AssertNoNaN(far);
            Assert.That(far.Status, Is.EqualTo(AimStatus.Solved));
            if (adaptive)
            {
                Assert.That(far.ElevationRadians, Is.EqualTo(near.ElevationRadians).Within(AimSolver.AngleTolerance));
                return false;
            }

            Assert.That(far.ElevationRadians, Is.EqualTo(near.ElevationRadians));
            Assert.That(far.Miss, Is.EqualTo(near.Miss));
            return true;
        }

        private static void AssertNoNaN(AimSolution s)
        {
            Assert.Multiple(() =>
            {
                Assert.That(s.Speed, Is.Not.NaN, "speed");
                Assert.That(s.ElevationRadians, Is.Not.NaN, "elevation");
                Assert.That(s.AzimuthFromTargetRadians, Is.Not.NaN, "azimuth");
                Assert.That(s.Velocity.IsFinite, Is.True, "velocity");
                Assert.That(s.AngularVelocity.IsFinite, Is.True, "spin");
                Assert.That(s.Arrival.IsFinite, Is.True, "arrival");
                Assert.That(s.Miss, Is.Not.NaN, "miss");
            });
        }

        [TestCase(false)]
        [TestCase(true)]
        public void ClearingANetBeyondDoubleRange_IsUnreachable(bool adaptive)
        {
            // The launch at x = -1e308, the net at x = +1e308: the signed distance is -2e308, -infinity (Plane.SignedDistance),
            // and the vacuum path to it infinite. Every trial lands long before: Unreachable with a Miss of +infinity.
            AimSolver solver = Solver(adaptive, Plane.Ground(Model));
            var net = new Plane(new Vector3d(1e308, 0, 0), Vector3d.UnitX);
            AimSolution s = solver.MinimumElevationToClear(new Vector3d(-1e308, 0, 1), 30, 0, Topspin, net, 0.914);
            TestContext.Out.WriteLine(s.ToString());
            Assert.That(s.Status, Is.EqualTo(AimStatus.Unreachable));
            AssertNoNaN(s);
            Assert.That(s.Miss, Is.EqualTo(double.PositiveInfinity));
        }

        [TestCase(false)]
        [TestCase(true)]
        public void ClearingANet_WithTheGroundAndNetPointsNear1e308AlongThem_IsTheNearSolve(bool adaptive)
        {
            // The launch at y = 1e308, the ground's and the net's given points at y = -1e308: the required height's point
            // (the ground's point plus up times the height) is 2e308 from every trial's arrival along y, so the plain margin
            // (arrival - point) . up was inf * 0 = NaN. Nothing depends on y (no wind, a uniform field), so the fixed-step
            // solve is the one with every point at y = 0, to the bit. The adaptive steps are not: their error control weighs
            // each component by its size (and the sidespin moves y, which a double at 1e308 does not resolve), so they
            // differ, and the root with them, within the solve's own refinement tolerance, AimSolver.AngleTolerance.
            AimSolution near = Solver(adaptive, Plane.Ground(Model)).MinimumElevationToClear(
                new Vector3d(0, 0, 1), 30, 0, Topspin, new Plane(new Vector3d(11.885, 0, 0), Vector3d.UnitX), 0.914);
            Assert.That(near.IsSolved, Is.True);

            AimSolver solver = Solver(adaptive, new Plane(new Vector3d(0, -1e308, 0), Vector3d.UnitZ));
            var net = new Plane(new Vector3d(11.885, -1e308, 0), Vector3d.UnitX);
            AimSolution far = solver.MinimumElevationToClear(new Vector3d(0, 1e308, 1), 30, 0, Topspin, net, 0.914);
            TestContext.Out.WriteLine(near.ToString());
            TestContext.Out.WriteLine(far.ToString());
            if (!AssertSolvedAsNear(far, near, adaptive))
            {
                return;
            }

            Assert.That(far.Simulations, Is.EqualTo(near.Simulations));
            Assert.That(far.Arrival.Position.X, Is.EqualTo(near.Arrival.Position.X));
            Assert.That(far.Arrival.Position.Z, Is.EqualTo(near.Arrival.Position.Z));
        }

        [Test]
        public void ClearingAHeightWhosePointExceedsADouble_IsRefusedNamingTheHeight()
        {
            // The required point, the ground's point plus its normal times the height, is (0, 0, 1.7e308 + 1e308): not a
            // double. Refused as bad input, naming the height, rather than flown against an infinite target.
            AimSolver solver = Solver(false, new Plane(new Vector3d(0, 0, 1.7e308), Vector3d.UnitZ));
            var net = new Plane(new Vector3d(11.885, 0, 0), Vector3d.UnitX);
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => solver.MinimumElevationToClear(new Vector3d(0, 0, 1.7e308), 30, 0, Topspin, net, 1e308));
            Assert.That(e!.ParamName, Is.EqualTo("height"));
            Assert.That(solver.MinimumElevationToClear(new Vector3d(0, 0, 1.7e308), 30, 0, Topspin, net, 1e306).Status, Is.EqualTo(AimStatus.Unreachable), "1e306 m up: no 30 m/s shot gets there");
        }

        private static readonly Vector3d[] FarTargets =
        {
            new Vector3d(20, -1e308, 0), // 2e308 away along the ground (the horizontal difference overflows)
            new Vector3d(1.7e308, 1e308, 0), // both horizontal differences near 1.7e308 and 1e308: finite, their length not
            new Vector3d(20, 0, 1.7e308), // 1.7e308 up: the rise is finite, its square is not
        };

        [Test]
        public void TargetSolves_ToATargetNear1e308Away_AreUnreachable([Values(0, 1, 2)] int which, [Values(false, true)] bool adaptive)
        {
            AimSolver solver = Solver(adaptive, Plane.Ground(Model));
            var start = new Vector3d(0, 1e308, 1);
            if (which == 1)
            {
                start = new Vector3d(-1e308, -1e308, 1);
            }

            Vector3d target = FarTargets[which];
            foreach (AimSolution s in new[]
                     {
                         solver.ElevationToReach(start, 30, Topspin, target),
                         solver.AnglesToReach(start, 30, Topspin, target),
                         solver.SpeedToReach(start, 0.2, 0, Topspin, target),
                     })
            {
                TestContext.Out.WriteLine(s.ToString());
                Assert.That(s.Status, Is.EqualTo(AimStatus.Unreachable));
                AssertNoNaN(s);
            }
        }

        [TestCase(false)]
        [TestCase(true)]
        public void Solves_WithSpinRatesNearTheLargestDouble_AreUnreachable_NotAnExceptionNamingState(bool adaptive)
        {
            // Finite rates of 1.7e308 rad/s each resolve, at most launch directions, to an angular velocity with an infinite
            // component (its true length is 2.9e308): the trial's stepper refused the state with an ArgumentException
            // naming "state", a parameter no solve has. Such a trial now fails like a diverged one.
            AimSolver solver = Solver(adaptive, Plane.Ground(Model));
            var spin = new LaunchSpin(1.7e308, 1.7e308, -1.7e308);
            var start = new Vector3d(0, 0, 1);
            var target = new Vector3d(20, 20, 0);
            foreach (AimSolution s in new[]
                     {
                         solver.MinimumElevationToClear(start, 30, 0, spin, new Plane(new Vector3d(11.885, 0, 0), Vector3d.UnitX), 0.914),
                         solver.ElevationToReach(start, 30, spin, target),
                         solver.AnglesToReach(start, 30, spin, target),
                         solver.SpeedToReach(start, 0.2, 0, spin, target),
                     })
            {
                Assert.That(s.Status, Is.EqualTo(AimStatus.Unreachable), s.ToString());
                AssertNoNaN(s);
            }
        }

        [TestCase(5e-324)]
        [TestCase(1e-322)]
        public void SpeedToReach_WithAMaximumSpeedWhoseOnePercentRoundsToZero_Ends(double maximumSpeed)
        {
            // The fallback scan steps up in 1 % of the maximum speed until past it: below about 1e-322 m/s that 1 % rounds to
            // 0 and the loop never ended (found by hand, 2026-12-02). Now it also counts its passes.
            var solver = new AimSolver(Model, Plane.Ground(Model), maximumSpeed: maximumSpeed);
            AimSolution s = solver.SpeedToReach(new Vector3d(0, 0, 1), 0.2, 0, Topspin, new Vector3d(20, 0, 0));
            Assert.That(s.Status, Is.EqualTo(AimStatus.Unreachable), s.ToString());
            AssertNoNaN(s);
        }

        [TestCase(false)]
        [TestCase(true)]
        public void Solves_AtSpeedsNearTheLargestDouble_AreAnswered_NotAnExceptionNamingState(bool adaptive)
        {
            // Found by hand (2026-12-02): with a maximum speed of double.MaxValue, SpeedToReach's scan stepped past it to an
            // infinite speed (its end test, MaximumSpeed (1 + 1e-12), was infinite), and the trial's stepper threw naming
            // "state" on the infinite velocity (52 of 400 random solves of the four kinds in a throwaway probe). The scan now
            // stops at double.MaxValue, and any trial whose velocity is not finite fails like a diverged one.
            var solver = adaptive
                ? new AimSolver(Model, Plane.Ground(Model), maximumSpeed: double.MaxValue)
                : new AimSolver(Model, RungeKutta4.Instance, 1.0 / 120, Plane.Ground(Model), maximumSpeed: double.MaxValue);
            var random = new Random(3);
            var start = new Vector3d(0, 0, 1);
            // Adaptive trials at 1e308 m/s shrink their steps until the solve's work cap (about 80 ms a solve): one of each.
            int solves = adaptive ? 4 : 24;
            for (int i = 0; i < solves; i++)
            {
                var target = new Vector3d(random.NextDouble() * 40 - 20, random.NextDouble() * 40 - 20, random.NextDouble() * 4);
                double speed = double.MaxValue * (1 - random.NextDouble() * 1e-15);
                AimSolution s = (i % 4) switch
                {
                    0 => solver.ElevationToReach(start, speed, LaunchSpin.None, target, random.NextDouble() - 0.5),
                    1 => solver.AnglesToReach(start, speed, Topspin, target),
                    2 => solver.SpeedToReach(start, random.NextDouble() - 0.5, random.NextDouble() - 0.5, LaunchSpin.None, target),
                    _ => solver.MinimumElevationToClear(start, speed, random.NextDouble() - 0.5, LaunchSpin.None,
                        new Plane(new Vector3d(11.885, 0, 0), new Vector3d(1, random.NextDouble() - 0.5, 0)), 0.9),
                };
                AssertNoNaN(s);
                Assert.That(double.IsFinite(s.Speed), Is.True, s.ToString());
            }
        }

        [Test]
        public void TargetWhoseHorizontalPartIsRoundingBesideItsDistanceAlongUp_IsRefusedNamingTheTarget()
        {
            // From the stateful fuzz (seed 4242, with the check of parameter names): up is nearly -x (gravity
            // (-1.4e56, 5e-324, -6074) m/s^2) and the target 1.8e308 m along it; the horizontal part left by the projection,
            // 4e292 m, passed the 1e-6 m test and LaunchFrame refused it as "forward must not be parallel to up", naming
            // a parameter no solve has.
            var model = new FlightModel(new Ball(0.057, 0.033), new Air(1.21), new Vector3d(-1.4124989602019165E+56, 5E-324, -6073.55893625919));
            var solver = new AimSolver(model, Plane.Ground(model));
            var start = new Vector3d(-9.534145669295778E-262, 0, -7.9162698960304330E+174);
            var target = new Vector3d(-1.7976931348623157E+308, -0.0, -2.660083871908367E-20);
            Assert.That(Assert.Throws<ArgumentException>(() => solver.ElevationToReach(start, 30, Topspin, target))!.ParamName, Is.EqualTo("target"));
            Assert.That(Assert.Throws<ArgumentException>(() => solver.AnglesToReach(start, 30, Topspin, target))!.ParamName, Is.EqualTo("target"));
            Assert.That(Assert.Throws<ArgumentException>(() => solver.SpeedToReach(start, 0.2, 0, Topspin, target))!.ParamName, Is.EqualTo("target"));
        }

        [TestCase(false)]
        [TestCase(true)]
        public void TargetSolve_WithLaunchAndTargetFarAlongTheSameLine_IsTheNearSolve(bool adaptive)
        {
            // Launch and target both at y = 1e308: their difference is finite (the near one); only the absolute positions
            // are large. The solve is the near one's (nothing depends on y), to the bit with fixed steps; with adaptive ones
            // within AimSolver.AngleTolerance (their error control weighs y by its size, see above).
            // Topspin only: with sidespin the ball moves along y, which at y = 1e308 a double cannot resolve.
            AimSolver solver = Solver(adaptive, Plane.Ground(Model));
            var topspin = new LaunchSpin(Spin.FromRpm(1200));
            AimSolution near = solver.ElevationToReach(new Vector3d(0, 0, 1), 30, topspin, new Vector3d(22, 0, 0));
            AimSolution far = solver.ElevationToReach(new Vector3d(0, 1e308, 1), 30, topspin, new Vector3d(22, 1e308, 0));
            Assert.That(near.IsSolved, Is.True);
            AssertSolvedAsNear(far, near, adaptive);
        }
    }
}
