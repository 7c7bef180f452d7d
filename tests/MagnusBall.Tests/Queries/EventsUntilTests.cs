using System;
using MagnusBall.Integration;
using MagnusBall.Queries;
using NUnit.Framework;

namespace MagnusBall.Tests.Queries
{
    /// <summary>The one "nothing after the landing" rule (FlightEventSet.CountUntil, FlightStepper.EventsUntil) that the predictor, the aim solver and the CLI share.</summary>
    [TestFixture]
    public class EventsUntilTests
    {
        private static FlightEvent At(FlightEventKinds kind, double time, int plane = -1) =>
            new FlightEvent(kind, plane, new FlightState(new Vector3d(time, 0, 0), Vector3d.UnitX, Vector3d.Zero, time));

        [Test]
        public void CountUntil_KeepsTheEventsBeforeTheStopAndAtItsInstant()
        {
            FlightEvent[] events =
            {
                At(FlightEventKinds.Apex, 0.1), At(FlightEventKinds.PlaneCrossing, 0.2, 0), At(FlightEventKinds.Landing, 0.3),
                At(FlightEventKinds.PlaneCrossing, 0.3, 1), At(FlightEventKinds.PlaneCrossing, 0.4, 2),
            };

            Assert.That(FlightEventSet.CountUntil(events, FlightEventKinds.Landing, out int stop), Is.EqualTo(4), "a crossing at the landing instant counts, the later one not");
            Assert.That(stop, Is.EqualTo(2));
            Assert.That(FlightEventSet.CountUntil(events, FlightEventKinds.PlaneCrossing, out stop), Is.EqualTo(2));
            Assert.That(stop, Is.EqualTo(1));
            Assert.That(FlightEventSet.CountUntil(events, FlightEventKinds.None, out stop), Is.EqualTo(5));
            Assert.That(stop, Is.EqualTo(-1));
            Assert.That(FlightEventSet.CountUntil(events.AsSpan(0, 2), FlightEventKinds.Landing, out stop), Is.EqualTo(2));
            Assert.That(stop, Is.EqualTo(-1));
            Assert.That(FlightEventSet.CountUntil(ReadOnlySpan<FlightEvent>.Empty, FlightEventKinds.All, out stop), Is.EqualTo(0));
            Assert.That(stop, Is.EqualTo(-1));
        }

        [Test]
        public void EventsUntil_OfTheLandingStep_DropsWhatComesAfterTheLanding()
        {
            // A long step (0.5 s) over the end of a tennis drive: it lands at about 0.83 s (x = 19.5 m) inside the step from 0.5 s to
            // 1.0 s, and a wall at 21 m, crossed only after the landing on the interpolant, must not count.
            FlightModel model = Shots.StepanekTennis(Gravity.ZUp);
            var wall = new Plane(new Vector3d(21, 0, 0), Vector3d.UnitX);
            var stepper = new FlightStepper(model, RungeKutta4.Instance, FlightEventSet.ForModel(model, wall));
            stepper.Reset(new FlightState(new Vector3d(0, 0, 1), new Vector3d(29, 0, 4), new Vector3d(0, 100, 0)));
            stepper.Step(0.5);
            stepper.Step(0.5);
            Assert.That(stepper.TryGetEvent(FlightEventKinds.Landing, out FlightEvent landing), Is.True);
            Assume.That(stepper.TryGetEvent(FlightEventKinds.PlaneCrossing, out FlightEvent late) && late.Time > landing.Time, Is.True, "the wall is crossed after the landing on this step's cubic");

            ReadOnlySpan<FlightEvent> counted = stepper.EventsUntil(FlightEventKinds.Landing, out bool stopped, out FlightEvent stop);
            Assert.That(stopped, Is.True);
            Assert.That(stop.Kind, Is.EqualTo(FlightEventKinds.Landing));
            Assert.That(stop.Time, Is.EqualTo(landing.Time));
            Assert.That(counted.Length, Is.EqualTo(stepper.Events.Length - 1));
            foreach (FlightEvent e in counted)
            {
                Assert.That(e.Time, Is.LessThanOrEqualTo(landing.Time), e.ToString());
            }

            Assert.That(stepper.EventsUntil(FlightEventKinds.None, out stopped, out _).Length, Is.EqualTo(stepper.Events.Length));
            Assert.That(stopped, Is.False);
        }
    }
}
