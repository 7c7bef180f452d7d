using MagnusBall.Flight;
using MagnusBall.Contact;
using MagnusBall.Integration;
using MagnusBall.Queries;
using MagnusBall.Stepping;
using NUnit.Framework;

namespace MagnusBall.Tests.Stepping
{
    /// <summary>A driver whose ball starts exactly on the ground (centre at the ground plane) moving level.</summary>
    [TestFixture]
    public class StartOnGroundTests
    {
        private const double Step = 1.0 / 240;

        private static readonly FlightModel Model = Shots.StepanekTennis(Gravity.ZUp);

        private static readonly FlightState Level = new FlightState(Vector3d.Zero, new Vector3d(10, 0, 0), Vector3d.Zero);

        [Test]
        public void WithoutBounce_LandsInTheFirstStep()
        {
            // Before: the ball fell through the floor (z = -77 m after 5 s) and the flight never ended.
            var driver = new FixedStepDriver(Model, RungeKutta4.Instance, Step, Level);
            var events = new FlightEvent[8];
            AdvanceResult result = driver.Advance(1.0 / 60, events);
            Assert.That(driver.IsFinished, Is.True);
            Assert.That(result.StepsTaken, Is.EqualTo(1));
            Assert.That(result.EventCount, Is.EqualTo(1));
            Assert.That(events[0].Kind, Is.EqualTo(FlightEventKinds.Landing));
            Assert.That(events[0].Time, Is.EqualTo(0));
            Assert.That(driver.State.Position, Is.EqualTo(Level.Position));
        }

        [Test]
        public void WithBounce_RollsOnTheGroundInsteadOfFallingThrough()
        {
            // BouncingFlight.Reset puts a ball placed on the court and not leaving it into rolling.
            var driver = new FixedStepDriver(Model, RungeKutta4.Instance, Step, Level, bounce: CrossBounce.Hard);
            for (int frame = 0; frame < 300 && !driver.IsFinished; frame++)
            {
                driver.Advance(1.0 / 60);
                Assert.That(driver.State.Position.Z, Is.GreaterThanOrEqualTo(0), $"frame {frame}");
            }

            Assert.That(driver.Phase, Is.Not.EqualTo(FlightPhase.Flying));
        }
    }
}
