using MagnusBall;
using UnityEngine;

namespace MagnusBall.Samples.TennisScene.Unity
{
    /// <summary>
    /// Draws the ball's predicted path to its next touch of the court with a <see cref="LineRenderer"/>,
    /// from the library's TrajectoryPredictor: before the launch from the inspector's launch state, in flight
    /// from the ball's current fixed state (after a bounce, the next arc). The prediction uses the same model,
    /// integrator and fixed step as the ball, so the ball follows the line exactly.
    /// </summary>
    /// <remarks>Buffers are allocated once; predicting allocates nothing per frame.</remarks>
    [RequireComponent(typeof(LineRenderer))]
    public class TrajectoryLine : MonoBehaviour
    {
        public TennisBall ball;
        [Tooltip("Most points drawn (one per fixed step).")]
        public int maxPoints = 2048;

        private LineRenderer _line;
        private ShotSimulation _simulation;
        private Vector3d[] _path;
        private Vector3[] _points;

        private void Awake()
        {
            _line = GetComponent<LineRenderer>();
            _line.useWorldSpace = true;
            _path = new Vector3d[maxPoints];
            _points = new Vector3[maxPoints];
        }

        private void LateUpdate()
        {
            if (ball == null || ball.Settings == null)
            {
                _line.positionCount = 0;
                return;
            }

            FlightState from = ball.Driver != null && ball.IsFlying ? ball.Driver.State : ball.LaunchState();
            if (_simulation == null || _simulation.Settings != ball.Settings)
            {
                _simulation = new ShotSimulation(ball.Settings); // only when the ball is relaunched with new settings
            }

            int count = _simulation.Predict(from, _path);
            _line.positionCount = count;
            for (int i = 0; i < count; i++)
            {
                _points[i] = UnityFrame.ToUnity(_path[i]);
                _line.SetPosition(i, _points[i]);
            }
        }
    }
}
