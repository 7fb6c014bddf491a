// SPDX-License-Identifier: GPL-3.0-or-later
// The learning algorithms of Li & Du (003): the geometric error's straight line (eq. 4) and the
// hybrid RBF network of appendix A, on data generated here from a known truth with noise.
#include "core/learning/hybrid_rbf.h"

#include <QTest>

#include <cmath>
#include <random>

using namespace tolturn;

namespace {

// A smooth residual over two inputs in µm: a bump (a warm-up hump, say) on a slope.
double truth(double x1, double x2)
{
    return 10.0 * std::exp(-((x1 - 0.3) * (x1 - 0.3) + (x2 - 0.6) * (x2 - 0.6)) / 0.05) + 3.0 * x1;
}

struct Samples {
    Eigen::MatrixXd x;
    Eigen::VectorXd y;     // with noise
    Eigen::VectorXd clean; // without
};

Samples samples(int n, double noise, bool signal, unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::normal_distribution<double> gauss(0.0, noise);
    Samples s{Eigen::MatrixXd(n, 2), Eigen::VectorXd(n), Eigen::VectorXd(n)};
    for (int i = 0; i < n; ++i) {
        s.x(i, 0) = uniform(random);
        s.x(i, 1) = uniform(random);
        s.clean[i] = signal ? truth(s.x(i, 0), s.x(i, 1)) : 0.0;
        s.y[i] = s.clean[i] + gauss(random);
    }
    return s;
}

double rms(const Eigen::VectorXd &v)
{
    return std::sqrt(v.squaredNorm() / double(v.size()));
}

Eigen::VectorXd predictions(const RbfNetwork &net, const Eigen::MatrixXd &x)
{
    Eigen::VectorXd f(x.rows());
    for (Eigen::Index i = 0; i < x.rows(); ++i)
        f[i] = net.predict(x.row(i).transpose());
    return f;
}

} // namespace

class TestLearning : public QObject {
    Q_OBJECT
private Q_SLOTS:

    // Li & Du's own line (eq. 4: δ_G = −0.121 φ − 3.519 µm, φ in mm) comes back from points on it.
    void lineThroughLiAndDusGeometricError()
    {
        std::vector<double> phi, delta;
        for (int i = 0; i < 10; ++i) { // ten diameters 20 mm apart, as their test artefact
            phi.push_back(20.0 + 20.0 * i);
            delta.push_back(-0.121 * phi.back() - 3.519);
        }
        const auto fit = fitLine(phi, delta);
        QVERIFY(fit.has_value());
        QVERIFY(std::abs(fit->slope + 0.121) < 1e-12);
        QVERIFY(std::abs(fit->intercept + 3.519) < 1e-10);
        QVERIFY(fit->residualRms < 1e-10);
        // By hand: (1, 1), (2, 3), (3, 2) → slope 0.5, intercept 1, residuals −0.5, 1, −0.5.
        const auto small = fitLine({1.0, 2.0, 3.0}, {1.0, 3.0, 2.0});
        QCOMPARE(small->slope, 0.5);
        QCOMPARE(small->intercept, 1.0);
        QVERIFY(std::abs(small->residualRms - std::sqrt(1.5 / 3.0)) < 1e-12);
        QVERIFY(!fitLine({2.0, 2.0}, {1.0, 3.0}).has_value());
    }

    // With a signal: the network predicts samples it has not seen to within 1.5 times the noise.
    void learnsASmoothResidual_data()
    {
        QTest::addColumn<int>("criterion");
        QTest::newRow("GCV") << int(RbfCriterion::Gcv);
        QTest::newRow("BIC") << int(RbfCriterion::Bic);
    }

    void learnsASmoothResidual()
    {
        QFETCH(int, criterion);
        constexpr double kNoise = 0.5;
        const Samples train = samples(400, kNoise, true, 1);
        const Samples test = samples(200, kNoise, true, 2);
        RbfTrainingOptions options;
        options.criterion = static_cast<RbfCriterion>(criterion);
        QString error;
        const auto net = trainHybridRbf(train.x, train.y, options, &error);
        QVERIFY2(net.has_value(), qPrintable(error));
        const double heldOut = rms(predictions(*net, test.x) - test.y);
        QVERIFY2(heldOut < 1.5 * kNoise,
                 qPrintable(QStringLiteral("held-out RMS %1 µm with %2 nodes").arg(heldOut).arg(net->nodes())));
        QVERIFY2(net->leaveOneOutRms < 1.5 * kNoise, qPrintable(QString::number(net->leaveOneOutRms)));
        // Less than the tree gave: the elimination took nodes out.
        QVERIFY(net->nodes() < net->treeNodes);
        // The signal itself is 10 µm high: without learning the error would be that.
        QVERIFY(rms(test.clean) > 4.0 * kNoise);
    }

    // Noise only: the network adds nothing, its predictions far inside the noise.
    void learnsNothingFromNoise()
    {
        constexpr double kNoise = 0.5;
        const Samples train = samples(400, kNoise, false, 3);
        const Samples test = samples(200, kNoise, false, 4);
        QString error;
        const auto net = trainHybridRbf(train.x, train.y, {}, &error);
        QVERIFY(net.has_value());
        const double added = rms(predictions(*net, test.x));
        QVERIFY2(added < 0.25 * kNoise, qPrintable(QStringLiteral("%1 µm from %2 nodes").arg(added).arg(net->nodes())));
    }

    void refusesTooFewOrBadSamples()
    {
        QString error;
        QVERIFY(!trainHybridRbf(Eigen::MatrixXd::Zero(2, 1), Eigen::VectorXd::Zero(2), {}, &error));
        QVERIFY(error.contains(QStringLiteral("at least 3")));
        Eigen::MatrixXd x = Eigen::MatrixXd::Zero(5, 1);
        x(2, 0) = std::nan("");
        QVERIFY(!trainHybridRbf(x, Eigen::VectorXd::Zero(5), {}, &error));
        QVERIFY(error.contains(QStringLiteral("finite")));
        QVERIFY(!trainHybridRbf(Eigen::MatrixXd::Zero(5, 1), Eigen::VectorXd::Zero(4), {}, &error));
    }
};

QTEST_GUILESS_MAIN(TestLearning)
#include "tst_learning.moc"
