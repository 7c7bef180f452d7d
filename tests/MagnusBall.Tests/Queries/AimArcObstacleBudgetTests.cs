using System;
using MagnusBall.Contact.Swings;
using MagnusBall.Integration;
using MagnusBall.Presets;
using MagnusBall.Queries;
using NUnit.Framework;

namespace MagnusBall.Tests.Queries
{
    /// <summary>
    /// Issue 39, item 3: aiming as a player thinks. The low or the high solution, a wall or net to clear on the way, the
    /// azimuth in the caller's own frame, and a work budget on every aim solve and swing inverse, with a target out of reach
    /// told cheaply. The work is counted (model evaluations plus steps), never timed.
    /// </summary>
    [TestFixture]
    public class AimArcObstacleBudgetTests
    {
        private const double G = 9.81;

        private static readonly FlightModel Vacuum = FlightModel.Vacuum(Ball.Tennis, new Vector3d(0, 0, -G));
        private static readonly FlightModel Tennis = SportPresets.Tennis.CreateModel(Air.SeaLevel, Gravity.ZUp);
        private static readonly FlightModel Golf = SportPresets.Golf.CreateModel(Air.SeaLevel, Gravity.ZUp);
        private static readonly FlightModel Soccer = SportPresets.Soccer.CreateModel(Air.SeaLevel, Gravity.ZUp);
        private static readonly LaunchFrame ZUp = new LaunchFrame(Vector3d.UnitZ, Vector3d.UnitX);
        private static readonly LaunchSpin Topspin = new LaunchSpin(20 * 2 * Math.PI);

        // Both kinds of trials are exact for the vacuum parabola (RK4 and the Hermite; Dormand-Prince and its quartic).
        private static AimSolver VacuumSolver(bool adaptive) =>
            adaptive
                ? new AimSolver(Vacuum, new Plane(default, Vector3d.UnitZ))
                : new AimSolver(Vacuum, RungeKutta4.Instance, 1.0 / 60, new Plane(default, Vector3d.UnitZ));

        // The vacuum parabola's height at a horizontal distance d from a launch at the ground.
        private static double Height(double elevation, double speed, double d) =>
            d * Math.Tan(elevation) - G * d * d / (2 * speed * speed * Math.Cos(elevation) * Math.Cos(elevation));

        [TestCase(false)]
        [TestCase(true)]
        public void High_IsTheLob_OfTheVacuumClosedForm_AndLow_StaysTheDrive(bool adaptive)
        {
            AimSolver solver = VacuumSolver(adaptive);
            double v = 20, range = 30, low = 0.5 * Math.Asin(G * range / (v * v));
            var target = new Vector3d(range, 0, 0);
            AimSolution drive = solver.ElevationToReach(default, v, LaunchSpin.None, target);
            AimSolution lob = solver.ElevationToReach(default, v, LaunchSpin.None, target, arc: AimArc.High);
            Assert.That(drive.IsSolved && lob.IsSolved, Is.True);
            Assert.That(drive.ElevationRadians, Is.EqualTo(low).Within(2e-8));
            Assert.That(lob.ElevationRadians, Is.EqualTo(0.5 * Math.PI - low).Within(2e-8), "the lob: the complement of the drive");

            AimSolution bothLob = solver.AnglesToReach(default, v, LaunchSpin.None, target, arc: AimArc.High);
            Assert.That(bothLob.IsSolved, Is.True);
            Assert.That(bothLob.ElevationRadians, Is.EqualTo(0.5 * Math.PI - low).Within(2e-8));
            Assert.That(bothLob.AzimuthFromTargetRadians, Is.EqualTo(0).Within(2e-8));
        }

        [TestCase(false)]
        [TestCase(true)]
        public void AWall_TheDriveHits_IsClearedByTheLob_AndOneThatStopsBoth_IsBlocked(bool adaptive)
        {
            AimSolver solver = VacuumSolver(adaptive);
            double v = 20, range = 30, wall = 10, r = Vacuum.Ball.Radius;
            double low = 0.5 * Math.Asin(G * range / (v * v)), high = 0.5 * Math.PI - low;
            var target = new Vector3d(range, 0, 0);
            double driveBottom = Height(low, v, wall) - r, lobBottom = Height(high, v, wall) - r; // 3.3 m and 15.1 m

            // Below the drive's bottom: the drive clears it, bit for bit the answer without a wall.
            AimSolution free = solver.ElevationToReach(default, v, LaunchSpin.None, target);
            AimSolution net = solver.ElevationToReach(default, v, LaunchSpin.None, target, obstacle: new AimObstacle(wall, driveBottom - 0.01));
            Assert.That(net.Status, Is.EqualTo(AimStatus.Solved));
            Assert.That(BitConverter.DoubleToInt64Bits(net.ElevationRadians), Is.EqualTo(BitConverter.DoubleToInt64Bits(free.ElevationRadians)));

            // Above it (by 1 cm: the ball's bottom, not its centre, must pass above): the lob.
            var tall = new AimObstacle(wall, driveBottom + 0.01);
            AimSolution over = solver.ElevationToReach(default, v, LaunchSpin.None, target, obstacle: tall);
            Assert.That(over.Status, Is.EqualTo(AimStatus.Solved));
            Assert.That(over.ElevationRadians, Is.EqualTo(high).Within(2e-8));
            AimSolution overBoth = solver.AnglesToReach(default, v, LaunchSpin.None, target, obstacle: tall);
            Assert.That(overBoth.Status, Is.EqualTo(AimStatus.Solved));
            Assert.That(overBoth.ElevationRadians, Is.EqualTo(high).Within(2e-8));

            // Asked for the drive only by its speed: SpeedToReach at the drive's elevation hits the wall.
            AimSolution bySpeed = solver.SpeedToReach(default, low, 0, LaunchSpin.None, target, tall);
            Assert.That(bySpeed.Status, Is.EqualTo(AimStatus.Blocked));

            // Above the lob's bottom too: Blocked, the miss how far the lob's bottom passes below the top.
            double top = lobBottom + 1;
            AimSolution blocked = solver.ElevationToReach(default, v, LaunchSpin.None, target, obstacle: new AimObstacle(wall, top));
            Assert.That(blocked.Status, Is.EqualTo(AimStatus.Blocked));
            Assert.That(blocked.IsSolved, Is.False);
            Assert.That(blocked.Miss, Is.EqualTo(-1).Within(1e-6));
            Assert.That(solver.AnglesToReach(default, v, LaunchSpin.None, target, obstacle: new AimObstacle(wall, top)).Status, Is.EqualTo(AimStatus.Blocked));
        }

        [Test]
        public void ATennisLob_OverAPlayerAtTheNet_LandsOnTheTarget_AboveTheDrive()
        {
            var solver = new AimSolver(Tennis, Plane.Ground(Tennis));
            var start = new Vector3d(0, 0, 1);
            var target = new Vector3d(23, 3, 0);
            AimSolution drive = solver.AnglesToReach(start, 25, Topspin, target);
            AimSolution lob = solver.AnglesToReach(start, 25, Topspin, target, obstacle: new AimObstacle(12, 3.2)); // a player's reach at the net
            TestContext.Out.WriteLine($"drive {drive}\nlob {lob}");
            Assert.That(drive.IsSolved && lob.IsSolved, Is.True);
            Assert.That(lob.Miss, Is.LessThan(1e-4));
            Assert.That(lob.ElevationDegrees, Is.GreaterThan(drive.ElevationDegrees + 20));
            // Bit for bit: the lob's search after the blocked drive flies the trials a lob solve of its own flies.
            AimSolution asked = solver.AnglesToReach(start, 25, Topspin, target, arc: AimArc.High);
            Assert.That(BitConverter.DoubleToInt64Bits(asked.ElevationRadians), Is.EqualTo(BitConverter.DoubleToInt64Bits(lob.ElevationRadians)),
                "the lowest launch that clears the player is the lob");
        }

        [Test]
        public void AzimuthDegreesIn_IsTheLaunchDirectionInTheCallersFrame_NotFromTheTarget()
        {
            // A curling free kick: the pitch's forward is +x, the target 3 m to the side at 20 m. The solve's own azimuth is
            // from the direction to the target; AzimuthDegreesIn(pitch) is the angle LaunchFrame.Direction takes there.
            var solver = new AimSolver(Soccer, Plane.Ground(Soccer));
            var start = new Vector3d(0, 0, Soccer.Ball.Radius);
            var target = new Vector3d(20, 3, 2);
            AimSolution kick = solver.AnglesToReach(start, 25, new LaunchSpin(0, -60), target);
            Assert.That(kick.IsSolved, Is.True);
            double inPitch = kick.AzimuthDegreesIn(ZUp);
            double toTarget = Math.Atan2(3, 20) * 180 / Math.PI;
            TestContext.Out.WriteLine($"from the target {kick.AzimuthFromTargetDegrees:F2} deg, in the pitch's frame {inPitch:F2} deg, target at {toTarget:F2} deg");
            Assert.That(inPitch, Is.EqualTo(kick.AzimuthFromTargetDegrees + toTarget).Within(1e-9));
            Vector3d direction = ZUp.Direction(kick.ElevationRadians, inPitch * Math.PI / 180);
            Assert.That((direction * kick.Speed - kick.Velocity).Length, Is.LessThan(1e-9), "LaunchFrame.Direction in the pitch's frame gives the solved launch");
            Assert.That(default(AimSolution).AzimuthDegreesIn(ZUp), Is.EqualTo(0));
        }

        [TestCase(false)]
        [TestCase(true)]
        public void ATargetOutOfReach_IsUnreachable_InAFewHundredEvaluations(bool high)
        {
            var solver = new AimSolver(Tennis, Plane.Ground(Tennis));
            AimArc arc = high ? AimArc.High : AimArc.Low;
            AimSolution e = solver.ElevationToReach(new Vector3d(0, 0, 1), 10, Topspin, new Vector3d(60, 0, 0), arc: arc);
            long elevationWork = solver.LastWork;
            AimSolution a = solver.AnglesToReach(new Vector3d(0, 0, 1), 10, Topspin, new Vector3d(60, 4, 0), arc: arc);
            long anglesWork = solver.LastWork;
            TestContext.Out.WriteLine($"elevation: {e.Simulations} flights, {elevationWork} evaluations; angles: {a.Simulations} flights, {anglesWork}");
            Assert.That(e.Status, Is.EqualTo(AimStatus.Unreachable));
            Assert.That(a.Status, Is.EqualTo(AimStatus.Unreachable));
            Assert.That(elevationWork, Is.LessThanOrEqualTo(1_000), "it scanned 63 full trials (about 9,000) before");
            Assert.That(anglesWork, Is.LessThanOrEqualTo(1_000));

            // A golf ball at 50 m/s with 5,000 rpm of backspin carries about 160 m: 300 m is out of reach, though not in a vacuum.
            var golf = new AimSolver(Golf, Plane.Ground(Golf), maximumFlightTime: 20);
            AimSolution far = golf.AnglesToReach(new Vector3d(0, 0, Golf.Ball.Radius), 50, new LaunchSpin(-5000 * Math.PI / 30), new Vector3d(300, 5, 0), arc: arc);
            TestContext.Out.WriteLine($"golf: {far.Simulations} flights, {golf.LastWork} evaluations");
            Assert.That(far.Status, Is.EqualTo(AimStatus.Unreachable));
            Assert.That(golf.LastWork, Is.LessThanOrEqualTo(2_500));
        }

        [Test]
        public void AClubFlagOutOfReach_IsUnreachable_WithinAFractionOfTheDefaultBudget()
        {
            // The new user's case: a 37 m/s club, the flag 170 m away. It took 40 iterations of up to 12 aim solves each
            // (4 s with RK4 trials); now the first step that leads out of reach and barely helps ends it.
            var solver = new AimSolver(Golf, Plane.Ground(Golf), maximumFlightTime: 20);
            var aim = new SwingAim(solver);
            Assert.That(aim.MaximumEvaluations, Is.EqualTo(60_000));
            var position = new Vector3d(0, 0, Golf.Ball.Radius);
            foreach (double loft in new[] { 8.0, 12.0, 16.0 })
            {
                SwingSolution<ClubSwing> s = aim.ClubFaceToReach(new ClubSwing(37, loft, -2), ZUp, position, new Vector3d(170, 3, 0));
                TestContext.Out.WriteLine($"loft {loft}: {s.Status}, {s.Iterations} iterations, {aim.LastWork} evaluations");
                Assert.That(s.Status, Is.EqualTo(AimStatus.Unreachable));
                Assert.That(aim.LastWork, Is.LessThanOrEqualTo(12_000));
            }

            // The same club at 40 m/s reaches it.
            SwingSolution<ClubSwing> reach = aim.ClubFaceToReach(new ClubSwing(40, 12, -2), ZUp, position, new Vector3d(170, 3, 0));
            TestContext.Out.WriteLine($"40 m/s: {reach.Status}, {reach.Iterations} iterations, {aim.LastWork} evaluations");
            Assert.That(reach.IsSolved, Is.True);
            Assert.That(aim.LastWork, Is.LessThanOrEqualTo(10_000));
        }

        [Test]
        public void TheWorkBudget_IsTheCallers_AndASolvePastIt_SaysSo()
        {
            Assert.That(new AimSolver(Tennis, Plane.Ground(Tennis)).MaximumEvaluations, Is.EqualTo(20_000), "adaptive default");
            Assert.That(new AimSolver(Tennis, RungeKutta4.Instance, 1.0 / 240, Plane.Ground(Tennis)).MaximumEvaluations, Is.EqualTo(1_000_000), "fixed-step default");

            // A corner with RK4 trials at 1/240 s takes several thousand evaluations: a budget of 1,000 stops it, within one
            // step of the budget.
            var small = new AimSolver(Tennis, RungeKutta4.Instance, 1.0 / 240, Plane.Ground(Tennis), maximumEvaluationsPerSolve: 1_000);
            AimSolution s = small.AnglesToReach(new Vector3d(0, 0, 1), 30, Topspin, new Vector3d(23.77, 4.1, 0));
            Assert.That(s.Status, Is.EqualTo(AimStatus.WorkLimitReached));
            Assert.That(small.LastWork, Is.LessThanOrEqualTo(1_000 + 20));

            // A swing inverse past its budget: WorkLimitReached, over it by at most one aim solve's smallest budget.
            var aim = new SwingAim(new AimSolver(Golf, Plane.Ground(Golf), maximumFlightTime: 20), 2_000);
            SwingSolution<ClubSwing> club = aim.ClubFaceToReach(new ClubSwing(40, 12, -2), ZUp, new Vector3d(0, 0, Golf.Ball.Radius), new Vector3d(170, 3, 0));
            Assert.That(club.Status, Is.EqualTo(AimStatus.WorkLimitReached));
            Assert.That(aim.LastWork, Is.LessThanOrEqualTo(2_000 + AimSolver.MinimumEvaluationsPerSolve + 20));
        }

        [Test]
        public void BadInput_IsRefused_NamingTheArgumentAndItsRange()
        {
            void Check(string name, TestDelegate action)
            {
                var e = (ArgumentException)Assert.Throws(Is.InstanceOf<ArgumentException>(), action)!;
                Assert.That(e.ParamName, Is.EqualTo(name));
                Assert.That(e.Message, Does.Contain(name));
            }

            var solver = new AimSolver(Tennis, Plane.Ground(Tennis));
            var p = new Vector3d(0, 0, 1);
            var t = new Vector3d(20, 0, 0);
            Check("distanceMeters", () => new AimObstacle(0, 1));
            Check("distanceMeters", () => new AimObstacle(double.NaN, 1));
            Check("topHeightMeters", () => new AimObstacle(5, double.PositiveInfinity));
            Check("obstacle", () => solver.ElevationToReach(p, 30, Topspin, t, obstacle: new AimObstacle(20, 1))); // at the target
            Check("obstacle", () => solver.AnglesToReach(p, 30, Topspin, t, obstacle: new AimObstacle(25, 1)));
            Check("obstacle", () => solver.SpeedToReach(p, 0.1, 0, Topspin, t, new AimObstacle(25, 1)));
            Check("arc", () => solver.ElevationToReach(p, 30, Topspin, t, arc: (AimArc)2));
            Check("arc", () => solver.AnglesToReach(p, 30, Topspin, t, arc: (AimArc)(-1)));
            Check("maximumEvaluationsPerSolve", () => new AimSolver(Tennis, Plane.Ground(Tennis), maximumEvaluationsPerSolve: 999));
            Check("maximumEvaluationsPerSolve", () => new AimSolver(Tennis, RungeKutta4.Instance, 0.01, Plane.Ground(Tennis), maximumEvaluationsPerSolve: 2_000_000_000));
            Check("maximumEvaluations", () => new SwingAim(solver, 10));
            Check("maximumEvaluations", () => new SwingAim(solver, Tennis.Ball, -1));
        }
    }
}
