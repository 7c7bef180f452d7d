using MagnusBall.Flight;
using MagnusBall;
using MagnusBall.Presets;
using MagnusBall.Queries;
using MagnusBall.Stepping;
using NUnit.Framework;

namespace MagnusBall.Tests.Runtime
{
    /// <summary>
    /// Runs inside Unity (Window > General > Test Runner, with "testables": ["com.magnusball.core"] in the
    /// project's Packages/manifest.json) and in CI (tests/MagnusBall.UnityScripts.Tests compiles this folder):
    /// the package's core flies a tennis ball in Unity's y-up frame as it does everywhere else. Only the NUnit
    /// constraint model is used, which Unity's NUnit 3.5 and NUnit 4 both have.
    /// </summary>
    [TestFixture]
    public class FlightInUnityFrameTests
    {
        private static FlightModel TennisInUnity() => SportPresets.Tennis.CreateModel(new Air(1.21), Gravity.YUp);

        private static FlightState Groundstroke(double topspinRpm)
        {
            var velocity = new Vector3d(0, 4.2, 29.7); // Unity: y up, z forward
            Vector3d spin = topspinRpm == 0 ? Vector3d.Zero : Spin.Topspin(velocity, Vector3d.UnitY, Spin.FromRpm(topspinRpm));
            return new FlightState(new Vector3d(0, 1, 0), velocity, spin);
        }

        private static FlightState FlyUntilLanded(FixedStepDriver driver, double frameSeconds)
        {
            // 10 s of frames at most: the shot lands after about 1 s.
            for (int frame = 0; frame < (int)(10 / frameSeconds) && !driver.IsFinished; frame++)
            {
                driver.Advance(frameSeconds);
            }

            Assert.That(driver.IsFinished, Is.True, "the ball lands within 10 s");
            return driver.State;
        }

        [Test]
        public void TheLanding_IsTheSameBits_At30And144FramesPerSecond()
        {
            FlightModel model = TennisInUnity();
            var at30 = new FixedStepDriver(model, 1.0 / 240, Groundstroke(1200), FlightEventSet.ForModel(model));
            var at144 = new FixedStepDriver(model, 1.0 / 240, Groundstroke(1200), FlightEventSet.ForModel(model));
            FlightState a = FlyUntilLanded(at30, 1.0 / 30);
            FlightState b = FlyUntilLanded(at144, 1.0 / 144);
            Assert.That(b.Position.X, Is.EqualTo(a.Position.X));
            Assert.That(b.Position.Z, Is.EqualTo(a.Position.Z));
            Assert.That(b.Time, Is.EqualTo(a.Time));
        }

        [Test]
        public void Topspin_DipsTheBall_InUnitysFrame()
        {
            FlightModel model = TennisInUnity();
            FlightState flat = FlyUntilLanded(new FixedStepDriver(model, 1.0 / 240, Groundstroke(0), FlightEventSet.ForModel(model)), 1.0 / 60);
            FlightState topspin = FlyUntilLanded(new FixedStepDriver(model, 1.0 / 240, Groundstroke(3000), FlightEventSet.ForModel(model)), 1.0 / 60);
            // The ground is y = 0 in Unity's frame; the topspin ball comes down sooner and shorter.
            Assert.That(topspin.Position.Y, Is.EqualTo(0).Within(1e-9));
            Assert.That(topspin.Position.Z, Is.LessThan(flat.Position.Z - 1.0), "3000 rpm of topspin shortens a 30 m/s drive by metres");
            Assert.That(topspin.Time, Is.LessThan(flat.Time));
        }
    }
}
