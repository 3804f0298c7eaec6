// BackgroundWriter, the thread that writes a run's fields while the
// stepping goes on. Truths checked, each without a clock: a submission
// returns while its job is still running (the stepping does not wait for
// the file); jobs run in the order they were submitted, and wait() returns
// once all have run; a job's error is thrown again on the submitting
// thread by the next submit() and by wait(), and the jobs queued after it
// are not run (their files would follow a missing one); a writer destroyed
// without wait() still runs every job it holds; and with one pending job
// allowed, a submission beyond it waits until the worker takes the pending
// one.
#include <thinlayer/output/background_writer.h>

#include <atomic>
#include <future>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "../common/truths.h"

using namespace thinlayer;
using truths::expect;

int
main()
{
  std::cout << "* a submission does not wait for its job\n";
  {
    BackgroundWriter         writer;
    std::promise<void>       release;
    std::atomic<bool>        ended(false);
    std::shared_future<void> released = release.get_future().share();
    writer.submit([released, &ended]() {
      released.wait();
      ended = true;
    });
    expect(!ended, "submit() returned with its job still running");
    release.set_value();
    writer.wait();
    expect(ended, "wait() returned once the job had ended");
  }

  std::cout << "* order\n";
  {
    std::vector<int> order;
    BackgroundWriter writer;
    for (int k = 0; k < 20; ++k)
      writer.submit([k, &order]() { order.push_back(k); });
    writer.wait();
    bool in_order = order.size() == 20;
    for (int k = 0; k < static_cast<int>(order.size()); ++k)
      in_order = in_order && order[k] == k;
    expect(in_order, "20 jobs ran, in the order submitted");
  }

  std::cout << "* a job's error\n";
  {
    BackgroundWriter         writer(4);
    std::promise<void>       release;
    std::shared_future<void> released = release.get_future().share();
    std::vector<int>         ran;
    writer.submit([released]() {
      released.wait();
      throw std::runtime_error("cannot write fields-0001.vtu");
    });
    writer.submit([&ran]() { ran.push_back(2); });
    writer.submit([&ran]() { ran.push_back(3); });
    release.set_value();
    std::string from_wait;
    try
      {
        writer.wait();
      }
    catch (const std::runtime_error &e)
      {
        from_wait = e.what();
      }
    expect(from_wait == "cannot write fields-0001.vtu",
           "wait() throws the job's error: '" + from_wait + "'");
    expect(ran.empty(), "the jobs queued after it did not run");
    expect(writer.failed(), "failed() says so");
    std::string from_submit;
    bool        later_ran = false;
    try
      {
        writer.submit([&later_ran]() { later_ran = true; });
      }
    catch (const std::runtime_error &e)
      {
        from_submit = e.what();
      }
    expect(from_submit == "cannot write fields-0001.vtu",
           "the next submit() throws it too");
    expect(!later_ran, "and its job is not run");
  }

  std::cout << "* destruction\n";
  {
    std::vector<int> ran;
    {
      BackgroundWriter writer(8);
      for (int k = 0; k < 8; ++k)
        writer.submit([k, &ran]() { ran.push_back(k); });
    }
    expect(ran.size() == 8,
           "a writer destroyed without wait() ran its " +
             std::to_string(ran.size()) + " of 8 jobs");
  }

  std::cout << "* at most one pending job\n";
  {
    BackgroundWriter         writer(1);
    std::promise<void>       release_first, first_started;
    std::shared_future<void> released = release_first.get_future().share();
    writer.submit([released, &first_started]() {
      first_started.set_value();
      released.wait();
    });
    // The worker holds the first job: the queue is empty again.
    first_started.get_future().wait();
    std::atomic<bool> third_submitted(false);
    writer.submit([]() {});
    // The queue is full: a third submission waits until the first job
    // ends and the worker takes the second.
    auto third = std::async(std::launch::async, [&]() {
      writer.submit([]() {});
      third_submitted = true;
    });
    // A bounded writer passes this in every order of the threads; an
    // unbounded one fails it whenever the third thread got there first.
    expect(!third_submitted,
           "a submission beyond the limit had not returned while the first "
           "job held the worker");
    release_first.set_value();
    third.wait();
    writer.wait();
    expect(third_submitted,
           "it returned once the worker had taken the second job");
  }

  return truths::conclude();
}
