using System;
using MagnusBall.Flight;
using MagnusBall.Aerodynamics;
using MagnusBall.Integration;
using MagnusBall.Queries;
using NUnit.Framework;

namespace MagnusBall.Tests.Queries
{
    [TestFixture]
    public class AimSolverTests
    {
        private const double G = 9.81;
        private const double Degree = Math.PI / 180;

        private static FlightModel Vacuum => FlightModel.Vacuum(Ball.Tennis, new Vector3d(0, 0, -G));

        // RK4 and the Hermite are exact for the vacuum parabola, so the solver's own tolerance (1e-8 rad,
        // 1e-8 m/s) and rounding are all that separate it from the closed forms.
        private static AimSolver VacuumSolver() => new AimSolver(Vacuum, RungeKutta4.Instance, 1.0 / 60, new Plane(default, Vector3d.UnitZ));

        // Dormand-Prince is exact for the parabola too (fifth order; its interpolant is quartic), so adaptive trials
        // meet the same closed forms.
        private static AimSolver AdaptiveVacuumSolver() => new AimSolver(Vacuum, new Plane(default, Vector3d.UnitZ));

        [Test]
        public void AdaptiveTrials_MatchTheVacuumClosedForms()
        {
            AimSolver solver = AdaptiveVacuumSolver();
            Assert.That(solver.IsAdaptive, Is.True);
            Assert.That(VacuumSolver().IsAdaptive, Is.False);
            double v = 20, range = 30;
            AimSolution s = solver.ElevationToReach(default, v, LaunchSpin.None, new Vector3d(range, 0, 0));
            Assert.That(s.IsSolved, Is.True);
            Assert.That(s.ElevationRadians, Is.EqualTo(0.5 * Math.Asin(G * range / (v * v))).Within(2e-8), "the low solution, not the lob");

            double e = 10 * Degree, x = 20, y0 = 1;
            AimSolution c = solver.SpeedToReach(new Vector3d(0, 0, y0), e, 0, LaunchSpin.None, new Vector3d(x, 0, 0));
            Assert.That(c.IsSolved, Is.True);
            Assert.That(c.Speed, Is.EqualTo(Math.Sqrt(G * x * x / (2 * Math.Cos(e) * Math.Cos(e) * (x * Math.Tan(e) + y0)))).Within(1e-7));

            // Through a point off to the side: azimuth atan(side / forward) exactly, elevation the range formula's.
            var target = new Vector3d(24, 7, 0);
            AimSolution b = solver.AnglesToReach(default, v, LaunchSpin.None, target);
            Assert.That(b.IsSolved, Is.True);
            Assert.That(b.AzimuthFromTargetRadians, Is.EqualTo(0).Within(2e-8), "the frame's forward points at the target");
            Assert.That(b.ElevationRadians, Is.EqualTo(0.5 * Math.Asin(G * 25 / (v * v))).Within(2e-8));
            Assert.That(b.Miss, Is.LessThan(1e-6));
        }

        [Test]
        public void AdaptiveTrial_ArrivesWhereAFineRk4FlightDoes()
        {
            // The stated trial accuracy (AimSolver.TrialTolerance): the solved shot's arrival, from its own adaptive trial,
            // against the same launch flown by RK4 at 1/1920 s (landing error below 1e-13 m at that step, docs/queries.md:
            // 6.8e-11 m at 1/240 s, fourth order). Bound: the documented 1e-8 m, three times over.
            var model = new FlightModel(new Ball(0.057, 0.033), new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(20));
            var solver = new AimSolver(model, Plane.Ground(model));
            var start = new Vector3d(0, 0, 1);
            var target = new Vector3d(23.77, 4.1, 0);
            AimSolution s = solver.AnglesToReach(start, 30, new LaunchSpin(Spin.FromRevolutionsPerSecond(20), Spin.FromRpm(600)), target);
            Assert.That(s.IsSolved, Is.True);
            var frame = new LaunchFrame(Vector3d.UnitZ, target - start);
            var plane = new Plane(target, frame.Forward);
            var predictor = new TrajectoryPredictor(model, RungeKutta4.Instance, 1.0 / 1920, FlightEventSet.ForModel(model, plane));
            Prediction p = predictor.Predict(s.LaunchState(start), 5, Span<Vector3d>.Empty, FlightEventKinds.PlaneCrossing | FlightEventKinds.Landing);
            double error = Vector3d.Distance(p.EndState.Position, s.Arrival.Position);
            TestContext.Out.WriteLine($"arrival: adaptive trial vs RK4 1/1920 s: {error:E2} m; miss {s.Miss:E2} m, {s.Simulations} flights");
            Assert.That(error, Is.LessThan(3e-8));
        }

        [Test]
        public void AdaptiveSolves_AllocateNothing_AndBadInputChangesNothing()
        {
            var model = Shots.StepanekTennis(Gravity.ZUp);
            var solver = new AimSolver(model, Plane.Ground(model));
            var net = new Plane(new Vector3d(11.885, 0, 0), Vector3d.UnitX);
            var spin = new LaunchSpin(Spin.FromRpm(1200), Spin.FromRpm(300));
            var start = new Vector3d(0, 0, 1);
            var target = new Vector3d(22, 2, 0);

            double Solve() =>
                solver.MinimumElevationToClear(start, 30, 0, spin, net, 0.914).ElevationRadians
                + solver.ElevationToReach(start, 30, spin, target).ElevationRadians
                + solver.AnglesToReach(start, 30, spin, target).AzimuthFromTargetRadians
                + solver.SpeedToReach(start, 10 * Degree, 0, spin, target).Speed;

            double first = Solve();
            double sum = 0;
            Action solve = () => sum = Solve();
            long allocated = Allocation.SteadyStateBytes(solve);
            Assert.That(allocated, Is.EqualTo(0));
            Assert.That(sum, Is.EqualTo(first), "a solve depends on its arguments only");

            // Refused input names the parameter, and the next solve is the same as before it.
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => solver.AnglesToReach(start, -1, spin, target))!.ParamName, Is.EqualTo("speed"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => solver.AnglesToReach(start, 30, spin, target, 90))!.ParamName, Is.EqualTo("maximumAzimuthDegrees"));
            Assert.That(Assert.Throws<ArgumentException>(() => solver.SpeedToReach(start, 0.1, 0, spin, start + new Vector3d(0, 0, 3)))!.ParamName, Is.EqualTo("target"));
            Assert.That(Solve(), Is.EqualTo(first));

            Assert.That(Assert.Throws<ArgumentNullException>(() => new AimSolver(null!, Plane.Ground(model)))!.ParamName, Is.EqualTo("model"));
            Assert.That(Assert.Throws<ArgumentException>(() => new AimSolver(FlightModel.Vacuum(Ball.Tennis, Vector3d.Zero), new Plane(default, Vector3d.UnitZ)))!.ParamName, Is.EqualTo("model"));
            Assert.That(Assert.Throws<ArgumentException>(() => new AimSolver(model, default(Plane)))!.ParamName, Is.EqualTo("ground"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new AimSolver(model, Plane.Ground(model), maximumFlightTime: double.NaN))!.ParamName, Is.EqualTo("maximumFlightTime"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new AimSolver(model, Plane.Ground(model), elevationScanDegrees: 1e-6))!.ParamName, Is.EqualTo("elevationScanDegrees"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => new AimSolver(model, null!, 0.01, Plane.Ground(model)))!.ParamName, Is.EqualTo("integrator"));
        }

        [Test]
        public void ElevationToReach_MatchesTheVacuumRangeFormula()
        {
            double v = 20, range = 30;
            AimSolution s = VacuumSolver().ElevationToReach(default, v, LaunchSpin.None, new Vector3d(range, 0, 0));
            double expected = 0.5 * Math.Asin(G * range / (v * v));
            Assert.That(s.IsSolved, Is.True);
            Assert.That(s.ElevationRadians, Is.EqualTo(expected).Within(2e-8), "the low solution, not the lob");
            Assert.That(s.Miss, Is.LessThan(1e-6));
        }

        [Test]
        public void MinimumElevationToClear_MatchesTheVacuumClosedForm()
        {
            double v = 25, x = 12, y0 = 1, h = 0.9;
            AimSolution s = VacuumSolver().MinimumElevationToClear(
                new Vector3d(0, 0, y0), v, 0, LaunchSpin.None, new Plane(new Vector3d(x, 0, 0), Vector3d.UnitX), h);

            // y0 + x T - a (1 + T^2) = h with T = tan(elevation), a = g x^2 / (2 v^2): the lower root.
            double a = G * x * x / (2 * v * v);
            double t = (x - Math.Sqrt(x * x - 4 * a * (a + h - y0))) / (2 * a);
            Assert.That(s.IsSolved, Is.True);
            Assert.That(s.ElevationRadians, Is.EqualTo(Math.Atan(t)).Within(2e-8));
            Assert.That(s.Arrival.Position.Z, Is.EqualTo(h).Within(1e-6));
            Assert.That(s.Arrival.Position.Z, Is.GreaterThanOrEqualTo(h), "the returned elevation clears");
        }

        [Test]
        public void SpeedToReach_MatchesTheVacuumClosedForm()
        {
            double e = 10 * Degree, x = 20, y0 = 1;
            AimSolution s = VacuumSolver().SpeedToReach(new Vector3d(0, 0, y0), e, 0, LaunchSpin.None, new Vector3d(x, 0, 0));
            double expected = Math.Sqrt(G * x * x / (2 * Math.Cos(e) * Math.Cos(e) * (x * Math.Tan(e) + y0)));
            Assert.That(s.IsSolved, Is.True);
            Assert.That(s.Speed, Is.EqualTo(expected).Within(1e-7));
        }

        [Test]
        public void AnglesToReach_PutsACurvingBallThroughTheTarget()
        {
            var model = Shots.StepanekTennis(Gravity.ZUp);
            var solver = new AimSolver(model, RungeKutta4.Instance, 1.0 / 120, Plane.Ground(model));
            var target = new Vector3d(20, -2, 1.5);
            var spin = new LaunchSpin(Spin.FromRpm(1500), Spin.FromRpm(1200));
            AimSolution s = solver.AnglesToReach(new Vector3d(0, 0, 1), 28, spin, target);
            Assert.That(s.IsSolved, Is.True);
            Assert.That(s.Miss, Is.LessThan(1e-5));

            // The solved launch, flown by the predictor, really passes the target.
            var frame = new LaunchFrame(Vector3d.UnitZ, target - new Vector3d(0, 0, 1));
            var plane = new Plane(target, frame.Forward);
            var predictor = new TrajectoryPredictor(model, RungeKutta4.Instance, 1.0 / 120, FlightEventSet.ForModel(model, plane));
            Prediction p = predictor.Predict(s.LaunchState(new Vector3d(0, 0, 1)), 5, Span<Vector3d>.Empty, FlightEventKinds.PlaneCrossing);
            Assert.That(Vector3d.Distance(p.EndState.Position, target), Is.LessThan(1e-5));
        }

        [Test]
        public void OutOfReach_IsUnreachableNotAnException()
        {
            AimSolver solver = VacuumSolver();
            Assert.That(solver.ElevationToReach(default, 10, LaunchSpin.None, new Vector3d(200, 0, 0)).Status, Is.EqualTo(AimStatus.Unreachable));
            Assert.That(solver.AnglesToReach(default, 10, LaunchSpin.None, new Vector3d(200, 30, 0)).Status, Is.EqualTo(AimStatus.Unreachable));
            Assert.That(
                solver.MinimumElevationToClear(default, 10, 0, LaunchSpin.None, new Plane(new Vector3d(5, 0, 0), Vector3d.UnitX), 50).Status,
                Is.EqualTo(AimStatus.Unreachable));
            Assert.That(solver.SpeedToReach(default, -30 * Degree, 0, LaunchSpin.None, new Vector3d(20, 0, 5)).Status, Is.EqualTo(AimStatus.Unreachable));

            // A plane behind the player is never crossed along its normal: that is a wrong argument (most likely the
            // plane's normal points the wrong way), not an unreachable shot (LaunchAndSegmentInputTests).
            var behind = Assert.Throws<ArgumentException>(
                () => solver.MinimumElevationToClear(new Vector3d(10, 0, 1), 20, 0, LaunchSpin.None, new Plane(default, Vector3d.UnitX), 1));
            Assert.That(behind!.ParamName, Is.EqualTo("position"));
        }

        [TestCase(false)]
        [TestCase(true)]
        public void ATargetBelowTheGround_IsAimedAtWhereTheBallComesDownOverIt_WithItsDepthAsTheMiss(bool adaptive)
        {
            // A trial stops where it lands, so no flight from above the ground passes through a point below it; the
            // documented answer (class remarks) is the launch that lands at the target's horizontal position, Solved, with
            // Miss the target's depth. The common case: a target on the court with the ground plane at the ball's
            // centre, one radius up (Miss = the radius). In a vacuum the landing point is also the closed form's.
            AimSolver solver = adaptive ? AdaptiveVacuumSolver() : VacuumSolver();
            var position = new Vector3d(0, 0, 1);
            foreach (double depth in new[] { 0.033, 5.0 })
            {
                var target = new Vector3d(20, 0, -depth);
                AimSolution elevation = solver.ElevationToReach(position, 30, LaunchSpin.None, target);
                AimSolution angles = solver.AnglesToReach(position, 30, LaunchSpin.None, target);
                AimSolution speed = solver.SpeedToReach(position, 10 * Degree, 0, LaunchSpin.None, target);
                foreach (AimSolution s in new[] { elevation, angles, speed })
                {
                    Assert.That(s.Status, Is.EqualTo(AimStatus.Solved), $"depth {depth} m");
                    // On the ground (the plane z = 0), at the target's horizontal position: to the solver's 1e-8 rad (or
                    // 1e-8 m/s) over 20 m, about 1e-6 m.
                    Assert.That(s.Arrival.Position.Z, Is.EqualTo(0).Within(1e-6), "it lands");
                    Assert.That(s.Arrival.Position.X, Is.EqualTo(20).Within(1e-6), "over the target");
                    Assert.That(s.Arrival.Position.Y, Is.EqualTo(0).Within(1e-6));
                    Assert.That(s.Miss, Is.EqualTo(depth).Within(1e-6), "the miss is the depth");
                }

                // The vacuum's closed form for landing at x = 20 m from 1 m up at 30 m/s: the lower root of
                // tan(e) = (v^2 -+ sqrt(v^4 - g (g x^2 - 2 h v^2))) / (g x) with h = 1 m above the landing.
                double v = 30, x = 20, h = 1;
                double low = Math.Atan((v * v - Math.Sqrt(v * v * v * v - G * (G * x * x - 2 * h * v * v))) / (G * x));
                Assert.That(elevation.ElevationRadians, Is.EqualTo(low).Within(2e-8));
            }
        }

        [Test]
        public void LaunchSpin_TurnsWithTheAim()
        {
            var frame = new LaunchFrame(Vector3d.UnitZ, Vector3d.UnitX);
            for (int az = -60; az <= 60; az += 30)
            {
                Vector3d d = frame.Direction(8 * Degree, az * Degree);
                Vector3d w = new LaunchSpin(100).AngularVelocity(d, frame);
                Assert.That((w - Spin.Topspin(d, Vector3d.UnitZ, 100)).Length, Is.LessThan(1e-12), "topspin by effect");
                Vector3d side = new LaunchSpin(0, 100).AngularVelocity(d, frame);
                Assert.That(Vector3d.Dot(side, d), Is.EqualTo(0).Within(1e-12));
                Assert.That(side.Length, Is.EqualTo(100).Within(1e-12));
                Assert.That(Vector3d.Dot(Vector3d.Cross(side, d), frame.Side), Is.GreaterThan(0), "sidespin pushes toward the side");
            }
        }

        [Test]
        public void Solves_AllocateNothing()
        {
            var model = Shots.StepanekTennis(Gravity.ZUp);
            var solver = new AimSolver(model, RungeKutta4.Instance, 1.0 / 60, Plane.Ground(model));
            var net = new Plane(new Vector3d(11.885, 0, 0), Vector3d.UnitX);
            var spin = new LaunchSpin(Spin.FromRpm(1200), Spin.FromRpm(300));
            var start = new Vector3d(0, 0, 1);
            var target = new Vector3d(22, 2, 0);

            double Solve() =>
                solver.MinimumElevationToClear(start, 30, 0, spin, net, 0.914).ElevationRadians
                + solver.ElevationToReach(start, 30, spin, target).ElevationRadians
                + solver.AnglesToReach(start, 30, spin, target).AzimuthFromTargetRadians
                + solver.SpeedToReach(start, 10 * Degree, 0, spin, target).Speed;

            double sum = 0;
            Action solve = () => sum = Solve();
            long allocated = Allocation.SteadyStateBytes(solve);
            Assert.That(allocated, Is.EqualTo(0));
            Assert.That(double.IsFinite(sum), Is.True);
        }

        [Test]
        public void BadInput_NamesTheParameter()
        {
            AimSolver solver = VacuumSolver();
            var target = new Vector3d(10, 0, 0);
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => solver.ElevationToReach(default, double.NaN, LaunchSpin.None, target))!.ParamName, Is.EqualTo("speed"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => solver.ElevationToReach(default, -1, LaunchSpin.None, target))!.ParamName, Is.EqualTo("speed"));
            Assert.That(Assert.Throws<ArgumentException>(() => solver.ElevationToReach(default, 10, LaunchSpin.None, new Vector3d(0, 0, 5)))!.ParamName, Is.EqualTo("target"));
            Assert.That(Assert.Throws<ArgumentException>(() => solver.ElevationToReach(default, 10, LaunchSpin.None, new Vector3d(double.NaN, 0, 0)))!.ParamName, Is.EqualTo("target"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => solver.SpeedToReach(default, 2, 0, LaunchSpin.None, target))!.ParamName, Is.EqualTo("elevationRadians"));
            Assert.That(Assert.Throws<ArgumentException>(() => solver.MinimumElevationToClear(default, 10, 0, LaunchSpin.None, new Plane(default, Vector3d.UnitZ), 1))!.ParamName, Is.EqualTo("plane"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new LaunchSpin(double.NaN))!.ParamName, Is.EqualTo("topspin"));
            Assert.That(Assert.Throws<ArgumentException>(() => new AimSolver(FlightModel.Vacuum(Ball.Tennis, Vector3d.Zero), RungeKutta4.Instance, 0.01, new Plane(default, Vector3d.UnitZ)))!.ParamName, Is.EqualTo("model"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new AimSolver(Vacuum, RungeKutta4.Instance, 0.01, new Plane(default, Vector3d.UnitZ), minimumElevationDegrees: 10, maximumElevationDegrees: 5))!.ParamName, Is.EqualTo("maximumElevationDegrees"));
            // Bounded work: a scan of 1e-6 degree over the default 125 degrees would fly 1.25e8 trials per solve.
            var fine = Assert.Throws<ArgumentOutOfRangeException>(() => new AimSolver(Vacuum, RungeKutta4.Instance, 0.01, new Plane(default, Vector3d.UnitZ), elevationScanDegrees: 1e-6))!;
            Assert.That(fine.ParamName, Is.EqualTo("elevationScanDegrees"));
            Assert.That(fine.Message, Does.Contain("0.0125"));
            Assert.That(new AimSolver(Vacuum, RungeKutta4.Instance, 0.01, new Plane(default, Vector3d.UnitZ), elevationScanDegrees: 0.0125).ElevationScanRadians, Is.GreaterThan(0), "the finest allowed scan");
            Assert.That(Assert.Throws<ArgumentException>(() => new LaunchFrame(Vector3d.UnitZ, new Vector3d(0, 0, 2)))!.ParamName, Is.EqualTo("forward"));
        }
    
        [Test]
        public void ASolve_GivesTheSameBits_WhateverTheSolverSolvedBefore()
        {
            // Adaptive trials after a solve's first start with the step that first trial's controller asked for; that step
            // belongs to the solve, so a solve's answer must not depend on what the solver did before it (it would, were the
            // step carried from one solve to the next).
            var model = new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(20));
            var start = new Vector3d(0, 0, 1);
            var spin = new LaunchSpin(Spin.FromRevolutionsPerSecond(20));
            var net = new Plane(new Vector3d(11.885, 0, 0), Vector3d.UnitX);
            var solves = new Func<AimSolver, AimSolution>[]
            {
                s => s.ElevationToReach(start, 30, spin, new Vector3d(23.77, 0, 0)),
                s => s.AnglesToReach(start, 30, spin, new Vector3d(23.77, 4.1, 0)),
                s => s.SpeedToReach(start, 8 * Math.PI / 180, 0, spin, new Vector3d(23.77, 0, 0)),
                s => s.MinimumElevationToClear(start, 30, 0, spin, net, 0.914),
                s => s.ElevationToReach(start, 12, new LaunchSpin(Spin.FromRevolutionsPerSecond(-40)), new Vector3d(9, -1, 0)),
            };
            for (int i = 0; i < solves.Length; i++)
            {
                AimSolution fresh = solves[i](new AimSolver(model, Plane.Ground(model)));
                Assert.That(fresh.IsSolved, Is.True, $"solve {i}");
                var used = new AimSolver(model, Plane.Ground(model));
                for (int j = solves.Length - 1; j >= 0; j--)
                {
                    solves[j](used); // every solve, this one included, before it is solved again
                }

                AimSolution again = solves[i](used);
                Assert.That(BitConverter.DoubleToInt64Bits(again.ElevationRadians), Is.EqualTo(BitConverter.DoubleToInt64Bits(fresh.ElevationRadians)), $"solve {i}: elevation");
                Assert.That(BitConverter.DoubleToInt64Bits(again.AzimuthFromTargetRadians), Is.EqualTo(BitConverter.DoubleToInt64Bits(fresh.AzimuthFromTargetRadians)), $"solve {i}: azimuth");
                Assert.That(BitConverter.DoubleToInt64Bits(again.Speed), Is.EqualTo(BitConverter.DoubleToInt64Bits(fresh.Speed)), $"solve {i}: speed");
                Assert.That(again.Simulations, Is.EqualTo(fresh.Simulations), $"solve {i}: flights");
            }
        }
}
}
